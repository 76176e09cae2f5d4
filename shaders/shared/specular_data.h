// What the camera sees in mirrors and glass (SpecularPass, specular/specular_trace.comp): which
// viewer pixels trace rays, the pass's parameter block and the weights of its two rays, written
// once for GLSL and C++.
#ifndef ISPM_SPECULAR_DATA_H
#define ISPM_SPECULAR_DATA_H

#include "host_device.h"
#include "photon_scatter.h"

ISPM_NAMESPACE_BEGIN

// From this Phong exponent on a lobe is traced as one mirror ray: cos^64 falls to half within
// 8 degrees of the mirror direction, about the blur a single ray leaves out. Broader lobes stay
// with the splats (their photons land across the lobe).
ISPM_CONST float kSpecularTraceMinExponent = 64.0f;
// Work group of specular_trace.comp (square tiles of pixels).
ISPM_CONST uint kSpecularGroupSize = 8u;
// Image unit of the 1x1 ambient estimate (specular_ambient.comp writes it, the trace reads it).
ISPM_CONST int kSpecularAmbientImage = 1;
// The most levels a pixel traces (setting specular_depth's maximum): the depth-first stack holds
// at most one ray more than the levels.
ISPM_CONST uint kMaxSpecularDepth = 6u;

// Parameters of specular_trace.comp (std140, at kBindingPassParams).
struct SpecularParams {
    uint levels;     // levels traced (specular_depth, at most bounces)
    float rayFloorM; // ray offset floor (GpuScene::getRayEpsilon)
    // Depth tolerance of a hit's reprojection onto a visible pixel (relative).
    float reprojectionTolerance;
    float pixelAngleRad; // the angle one pixel spans at the eye across the image's middle
};
ISPM_STATIC_ASSERT_SIZE(SpecularParams, 16);

// Whether a surface's specular lobe is traced as a mirror ray.
ISPM_INLINE bool isMirrorLobe(vec4 specularExponent) {
    return hasSpecularLobe(vec3(specularExponent)) &&
           specularExponent.w >= kSpecularTraceMinExponent;
}

ISPM_INLINE bool isTransmissive(vec4 transmissive) {
    return transmissive.x > 0.0f || transmissive.y > 0.0f || transmissive.z > 0.0f;
}

// The mirror ray's weight: the reference's Phong sample, f cos / pdf = rho_s (e + 2) / (e + 1)
// cos(theta_out) (photon_scatter.h), taken at the lobe's axis, where theta_out = theta_in and
// the pair's Fresnel angle is the incidence.
ISPM_INLINE vec3 computeMirrorWeight(vec3 diffuse, vec4 specularExponent, float cosIn) {
    float exponent = specularExponent.w;
    return computeSpecularAlbedo(diffuse, vec3(specularExponent), cosIn) *
           ((exponent + 2.0f) / (exponent + 1.0f) * cosIn);
}

ISPM_NAMESPACE_END

#endif
