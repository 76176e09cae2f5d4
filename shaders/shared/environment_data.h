// The environment (docs/design.md "Environment"): radiance arriving from every direction no
// surface blocks, a constant, the analytic sky of Preetham, Shirley and Smits (1999, "A
// practical analytic model for daylight") tied to the sun's direction, or an equirectangular
// image (its texels in a texture at kUnitEnvironmentImage, lib/environment.glsl). Shared by C++
// (budgets, tests) and GLSL (direct light, the path tracer, photons, what the camera sees).
#ifndef ISPM_ENVIRONMENT_DATA_H
#define ISPM_ENVIRONMENT_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

ISPM_CONST uint kEnvironmentNone = 0u;
ISPM_CONST uint kEnvironmentConstant = 1u;
ISPM_CONST uint kEnvironmentSky = 2u;
ISPM_CONST uint kEnvironmentImage = 3u;

// std430 at kBindingEnvironment; the sky's Perez coefficients are computed on the CPU
// (scene/environment.cpp) from the turbidity and the sun.
struct GpuEnvironment {
    uvec4 type;           // x = kEnvironment*; image: y = width, z = height (texels)
    vec4 radiance;        // constant: rgb W/(m^2 sr); sky: w = the scale on its radiance
    vec4 toSun;           // sky: xyz unit direction toward the sun, w = its zenith angle (rad)
    vec4 zenith;          // sky: x = Y (W/(m^2 sr) luminance-equivalent), y = x, z = y chromaticity
    vec4 perezY[2];       // A..E of the luminance (x of [1] = E)
    vec4 perezX[2];       // ... of chromaticity x
    vec4 perezChromaY[2]; // ... of chromaticity y
    // image: x, y = cos, sin of its rotation about +y; z = the sampling pdf's normaliser, 1 /
    // the mean over texels of luminance x sin(theta) (0: a black image, nothing to sample)
    vec4 image;
};
ISPM_STATIC_ASSERT_SIZE(GpuEnvironment, 176);

ISPM_CONST int kBindingEnvironment = 37;
// The image environment's texture (RGBA32F, width x (height + 1), texelFetch only): rows
// 0..height-1 the image, top row (the zenith) first, rgb its radiance W/(m^2 sr) (scale
// applied), a the row's conditional CDF at the texel's end; row `height`, r at x = row: the
// marginal CDF over rows at that row's end (docs/design.md "Environment"). Past scene_data.h's
// units (0..31, the normal maps' last): GL 4.5 guarantees 80 combined units, and a stage's limit
// (32 on llvmpipe) counts the samplers it uses, not the unit numbers.
ISPM_CONST int kUnitEnvironmentImage = 32;

ISPM_CONST float kEnvironmentPi = 3.14159265358979f;

// The equirectangular convention (docs/scene-format.md "environment"): v = theta / pi, theta
// the angle from +y (the top row is the zenith); u = 1/2 + phi / (2 pi), phi = atan2(x, -z), so
// the centre column looks toward -z, u = 3/4 toward +x and u = 0 and 1 toward +z. `rotation`
// (cos, sin of alpha) turns the image by alpha about +y (right-handed: +x toward -z).
ISPM_INLINE vec2 computeEnvironmentUv(vec3 toward, vec2 rotation) {
    // R_y(-alpha) takes the world direction back to the image's frame.
    float x = rotation.x * toward.x - rotation.y * toward.z;
    float z = rotation.y * toward.x + rotation.x * toward.z;
    float u = 0.5f + atan(x, -z) / (2.0f * kEnvironmentPi);
    float v = acos(clamp(toward.y, -1.0f, 1.0f)) / kEnvironmentPi;
    return vec2(clamp(u, 0.0f, 1.0f), v);
}

// The unit direction at image coordinates uv (the inverse of computeEnvironmentUv).
ISPM_INLINE vec3 computeEnvironmentDirection(vec2 uv, vec2 rotation) {
    float theta = uv.y * kEnvironmentPi;
    float phi = (uv.x - 0.5f) * 2.0f * kEnvironmentPi;
    float sinTheta = sin(theta);
    float x = sinTheta * sin(phi);
    float z = -sinTheta * cos(phi);
    return vec3(rotation.x * x + rotation.y * z, cos(theta), -rotation.y * x + rotation.x * z);
}

// The texel's weight in the sampling pdf: its luminance (Rec. 709) x sin(theta) at the centre of
// its row (the solid angle a texel covers), so that the pdf over (u, v) is constant per texel.
ISPM_INLINE float computeEnvironmentTexelWeight(vec3 radiance, uint row, uint height) {
    float sinTheta = sin((float(row) + 0.5f) / float(height) * kEnvironmentPi);
    return dot(radiance, vec3(0.2126f, 0.7152f, 0.0722f)) * sinTheta;
}

// The solid-angle pdf of a direction in a texel of weight `weight`, at polar angle theta with
// sin(theta) = sinTheta: the pdf over (u, v), weight x normaliser, over the Jacobian
// d(omega) / d(u v) = 2 pi^2 sin(theta).
ISPM_INLINE float computeEnvironmentSolidAnglePdf(float weight, float normaliser, float sinTheta) {
    if (!(sinTheta > 0.0f)) return 0.0f;
    return weight * normaliser / (2.0f * kEnvironmentPi * kEnvironmentPi * sinTheta);
}

// Perez's luminance distribution F(theta, gamma) for coefficients A..D (abcd) and E: theta the
// angle to the zenith, gamma the angle to the sun.
ISPM_INLINE float evaluatePerez(vec4 abcd, float e, float cosTheta, float gamma, float cosGamma) {
    return (1.0f + abcd.x * exp(abcd.y / cosTheta)) *
           (1.0f + abcd.z * exp(abcd.w * gamma) + e * cosGamma * cosGamma);
}

// Radiance W/(m^2 sr) arriving from unit direction `toward` (pointing away from the receiver).
// The sky sends nothing from below the horizon (the ground is the scene's own geometry). An
// image's texels are not in the struct: its callers read them (lib/environment.glsl's
// lookUpEnvironment, scene/environment.cpp's evaluateEnvironment); here it gives 0.
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
// from (the sphere; a sky: the downward hemisphere; an image: from its pdf) and enters the
// scene's bounding box through a point uniform over the box's outline seen along it
// (computeBoxOutlineArea, sampleBoxEntry), with the radiance from where it comes x that area x
// 4 pi (2 pi; an image: 1 / pdf) / photons.
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
