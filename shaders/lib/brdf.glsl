// Reflection models: Lambert plus normalised Phong around the mirror direction,
// rho_s (n + 2) / (2 pi) cos^n(alpha), split between the two by Schlick's Fresnel on materials
// with a specular part; written once in shared/surface_brdf.h for the photon roulette too.
#include "constants.glsl"
#include "../shared/surface_brdf.h"

// SURFACE_SPECULAR 0: the scene has no material with a specular part (GpuScene::
// getSurfaceDefines), so every BRDF is Lambert, rho_d / pi, which evaluateSurfaceBrdf would
// return too; llvmpipe would still pay for its Phong lobe at every pixel.
#ifndef SURFACE_SPECULAR
#define SURFACE_SPECULAR 1
#endif

vec3 evaluateBrdf(vec3 diffuse, vec4 specularExponent, vec3 n, vec3 wi, vec3 wo) {
#if SURFACE_SPECULAR
    return evaluateSurfaceBrdf(diffuse, specularExponent, n, wi, wo);
#else
    return diffuse * kInvPiF;
#endif
}

// The BRDF the splats shade a viewer pixel with (traceExponent:
// frame.specularTraceMinExponent): where
// the specular pass traces the pixel's lobe as a mirror ray, that ray carries all the light the
// lobe reflects but the lights' own (direct.frag), so the photons add only the diffuse lobe.
vec3 evaluateSplatBrdf(vec3 diffuse, vec4 specularExponent, vec3 n, vec3 wi, vec3 wo,
                       float traceExponent) {
#if SURFACE_SPECULAR
    if (traceExponent > 0.0 && hasSpecularLobe(specularExponent.rgb) &&
        specularExponent.w >= traceExponent) {
        return evaluateDiffuseLobe(diffuse, specularExponent.rgb, dot(n, wi), dot(n, wo));
    }
    return evaluateSurfaceBrdf(diffuse, specularExponent, n, wi, wo);
#else
    return diffuse * kInvPiF;
#endif
}
