// The reflection model, written once for GLSL (direct light, splats, the reference, and the photon
// roulette through photon_scatter.h) and C++ (tests). Lambert plus a normalised Phong lobe,
// rho_s (e + 2) / (2 pi) cos^e(alpha) around the mirror direction; on a material with a
// specular part the split between the two follows Schlick's Fresnel (thesis 5.3.2): at incidence
// cos(theta) the Schlick weight g = (1 - cos theta)^5 moves g of the diffuse reflectance into the
// specular lobe, so the lobes reflect
//     specular: rho_s + rho_d g        diffuse: rho_d (1 - g)
// (the material's values at normal incidence; their sum, and so energy, the same at every
// angle). A material without specular is plain Lambert. The BRDF stays reciprocal: the diffuse
// lobe takes (1 - g) of both directions, rescaled so its albedo is rho_d (1 - g) exactly, and the
// specular lobe g of the half-vector's angle (= the incidence at the mirror direction).
#ifndef ISPM_SURFACE_BRDF_H
#define ISPM_SURFACE_BRDF_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

ISPM_CONST float kInvPiF = 0.318309886183791f;
ISPM_CONST float kInvTwoPiF = 0.159154943091895f;
// 1 / (cosine-weighted mean of 1 - (1 - cos)^5 over the hemisphere) = 1 / (1 - 2/42): makes
// the coupled diffuse lobe's albedo rho_d (1 - g) (tests/unit/surface_brdf_test.cpp integrates it).
ISPM_CONST float kCoupledDiffuseScale = 21.0f / 20.0f;

// True for materials whose diffuse/specular split follows Fresnel: those with a specular part.
ISPM_INLINE bool hasSpecularLobe(vec3 specular) {
    return specular.x > 0.0f || specular.y > 0.0f || specular.z > 0.0f;
}

// Schlick's weight (1 - cos)^5 toward grazing; 0 where the material has no specular lobe.
ISPM_INLINE float computeSchlickWeight(float cosTheta, vec3 specular) {
    if (!hasSpecularLobe(specular)) return 0.0f;
    float m = 1.0f - clamp(cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

// The specular lobe's reflectance for a path arriving at cos(theta) to the normal.
ISPM_INLINE vec3 computeSpecularAlbedo(vec3 diffuse, vec3 specular, float cosTheta) {
    return specular + diffuse * computeSchlickWeight(cosTheta, specular);
}

// The diffuse lobe's reflectance for a path arriving at cos(theta) to the normal.
ISPM_INLINE vec3 computeDiffuseAlbedo(vec3 diffuse, vec3 specular, float cosTheta) {
    return diffuse * (1.0f - computeSchlickWeight(cosTheta, specular));
}

// Diffuse lobe: rho_d / pi, times kCoupledDiffuseScale (1 - g_in)(1 - g_out) with a specular
// part.
ISPM_INLINE vec3 evaluateDiffuseLobe(vec3 diffuse, vec3 specular, float cosIn, float cosOut) {
    if (!hasSpecularLobe(specular)) return diffuse * kInvPiF;
    float coupling = kCoupledDiffuseScale * (1.0f - computeSchlickWeight(cosIn, specular)) *
                     (1.0f - computeSchlickWeight(cosOut, specular));
    return diffuse * (kInvPiF * coupling);
}

// The specular lobe's reflectance for the pair (wi, wo): Fresnel at the half vector's angle.
ISPM_INLINE vec3 computePairSpecularAlbedo(vec3 diffuse, vec3 specular, vec3 wi, vec3 wo) {
    vec3 h = wi + wo;
    float len = sqrt(dot(h, h));
    float cosHalf = len > 0.0f ? dot(wi, h) / len : 0.0f; // opposite directions: grazing
    return computeSpecularAlbedo(diffuse, specular, cosHalf);
}

// f(wi, wo) for unit normal n and unit wi, wo on its side; specularExponent.w = Phong exponent.
ISPM_INLINE vec3 evaluateSurfaceBrdf(vec3 diffuse, vec4 specularExponent, vec3 n, vec3 wi,
                                     vec3 wo) {
    vec3 specular = vec3(specularExponent);
    vec3 f = evaluateDiffuseLobe(diffuse, specular, dot(n, wi), dot(n, wo));
    if (hasSpecularLobe(specular)) {
        float exponent = specularExponent.w;
        vec3 mirror = reflect(-wi, n);
        float cosAlpha = max(dot(mirror, wo), 0.0f);
        f = f + computePairSpecularAlbedo(diffuse, specular, wi, wo) *
                    ((exponent + 2.0f) * kInvTwoPiF * pow(cosAlpha, exponent));
    }
    return f;
}

ISPM_NAMESPACE_END

#endif
