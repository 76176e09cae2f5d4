// The environment (docs/design.md "Environment"): radiance arriving from every direction no
// surface blocks, a constant or the analytic sky of Preetham, Shirley and Smits (1999, "A
// practical analytic model for daylight") tied to the sun's direction. Shared by C++ (budgets,
// tests) and GLSL (direct light, the path tracer, photons, what the camera sees).
#ifndef ISPM_ENVIRONMENT_DATA_H
#define ISPM_ENVIRONMENT_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

ISPM_CONST uint kEnvironmentNone = 0u;
ISPM_CONST uint kEnvironmentConstant = 1u;
ISPM_CONST uint kEnvironmentSky = 2u;

// std430 at kBindingEnvironment; the sky's Perez coefficients are computed on the CPU
// (scene/environment.cpp) from the turbidity and the sun.
struct GpuEnvironment {
    uvec4 type;           // x = kEnvironment*
    vec4 radiance;        // constant: rgb W/(m^2 sr); sky: w = the scale on its radiance
    vec4 toSun;           // sky: xyz unit direction toward the sun, w = its zenith angle (rad)
    vec4 zenith;          // sky: x = Y (W/(m^2 sr) luminance-equivalent), y = x, z = y chromaticity
    vec4 perezY[2];       // A..E of the luminance (x of [1] = E)
    vec4 perezX[2];       // ... of chromaticity x
    vec4 perezChromaY[2]; // ... of chromaticity y
};
ISPM_STATIC_ASSERT_SIZE(GpuEnvironment, 160);

ISPM_CONST int kBindingEnvironment = 37;

// Perez's luminance distribution F(theta, gamma) for coefficients A..D (abcd) and E: theta the
// angle to the zenith, gamma the angle to the sun.
ISPM_INLINE float evaluatePerez(vec4 abcd, float e, float cosTheta, float gamma, float cosGamma) {
    return (1.0f + abcd.x * exp(abcd.y / cosTheta)) *
           (1.0f + abcd.z * exp(abcd.w * gamma) + e * cosGamma * cosGamma);
}

// Radiance W/(m^2 sr) arriving from unit direction `toward` (pointing away from the receiver).
// The sky sends nothing from below the horizon (the ground is the scene's own geometry).
ISPM_INLINE vec3 evaluateEnvironment(GpuEnvironment env, vec3 toward) {
    if (env.type.x == kEnvironmentConstant) return vec3(env.radiance);
    if (env.type.x != kEnvironmentSky || toward.y <= 0.0f) return vec3(0.0f);
    // Up to 89.4 degrees from the zenith: the model's exp(B / cos theta) stays finite.
    float cosTheta = max(toward.y, 0.01f);
    float cosGamma = clamp(dot(toward, vec3(env.toSun)), -1.0f, 1.0f);
    float gamma = acos(cosGamma);
    float cosSunTheta = cos(env.toSun.w);
    float sunGamma = env.toSun.w;
    float luminance = env.zenith.x *
                      evaluatePerez(env.perezY[0], env.perezY[1].x, cosTheta, gamma, cosGamma) /
                      evaluatePerez(env.perezY[0], env.perezY[1].x, 1.0f, sunGamma, cosSunTheta);
    float x = env.zenith.y *
              evaluatePerez(env.perezX[0], env.perezX[1].x, cosTheta, gamma, cosGamma) /
              evaluatePerez(env.perezX[0], env.perezX[1].x, 1.0f, sunGamma, cosSunTheta);
    float y =
        env.zenith.z *
        evaluatePerez(env.perezChromaY[0], env.perezChromaY[1].x, cosTheta, gamma, cosGamma) /
        evaluatePerez(env.perezChromaY[0], env.perezChromaY[1].x, 1.0f, sunGamma, cosSunTheta);
    // xyY to XYZ to linear sRGB (Rec. 709 primaries, D65).
    float bigX = x / y * luminance;
    float bigZ = (1.0f - x - y) / y * luminance;
    vec3 rgb = vec3(3.2406f * bigX - 1.5372f * luminance - 0.4986f * bigZ,
                    -0.9689f * bigX + 1.8758f * luminance + 0.0415f * bigZ,
                    0.0557f * bigX - 0.2040f * luminance + 1.0570f * bigZ);
    return max(rgb, vec3(0.0f)) * env.radiance.w;
}

// Photons from the environment (shaders/photon/environment_emit.comp, std140 at
// kBindingPassParams): each travels along a direction uniform over those the environment shines
// from (the sphere; a sky: the downward hemisphere) and enters the scene's bounding box through
// a point uniform over the box's outline seen along it (computeBoxOutlineArea,
// sampleBoxEntry), with the radiance from where it comes x that area x 4 pi (2 pi) / photons.
struct EnvironmentEmitParams {
    vec3 sceneMinW;
    float rayOffsetM;
    vec3 sceneExtentM;
    uint firstPhoton;
    uint photons;
    uint light; // the index its photons count under (after the lights and emitter groups)
    uint seed;
    uint rngGenerator;
    uint firstBounce;
    uint bounceCapacity;
    uint pad0;
    uint pad1;
};
ISPM_STATIC_ASSERT_SIZE(EnvironmentEmitParams, 64);

// The area (m^2) of a box of extent `extent` seen along unit direction `dir`: its faces facing
// `dir`, each by its cosine. Over all directions it averages a quarter of the box's surface
// (Cauchy), over a hemisphere's as well.
ISPM_INLINE float computeBoxOutlineArea(vec3 extent, vec3 dir) {
    return abs(dir.x) * extent.y * extent.z + abs(dir.y) * extent.x * extent.z +
           abs(dir.z) * extent.x * extent.y;
}

// A point uniform over the outline of the box (corner boxMin, extent `extent`) seen along unit
// `dir`, on the face a ray along `dir` enters by: the face among the three facing against `dir`
// picked by its share of computeBoxOutlineArea (u.x), a uniform point on it (u.yz).
ISPM_INLINE vec3 sampleBoxEntry(vec3 boxMin, vec3 extent, vec3 dir, vec3 u) {
    vec3 shares = abs(dir) * vec3(extent.y * extent.z, extent.x * extent.z, extent.x * extent.y);
    float pick = u.x * (shares.x + shares.y + shares.z);
    vec3 side =
        vec3(dir.x > 0.0f ? 0.0f : 1.0f, dir.y > 0.0f ? 0.0f : 1.0f, dir.z > 0.0f ? 0.0f : 1.0f);
    vec3 at = pick < shares.x              ? vec3(side.x, u.y, u.z)
              : pick < shares.x + shares.y ? vec3(u.y, side.y, u.z)
                                           : vec3(u.y, u.z, side.z);
    vec3 p = boxMin + extent * at;
    return p;
}

ISPM_CONST uint kEnvironmentEmitGroupSize = 64u;

ISPM_NAMESPACE_END

#endif
