// The environment's light (shared/environment_data.h, docs/design.md "Environment"): what it
// sends along a direction, an image environment's directions drawn from its pdf, and its direct
// light at a surface point, each sample with a ray through the BVH to the open sky. Needs
// scene_buffers.glsl, bvh.glsl, brdf.glsl and emitters.glsl (the sample sequence) included
// before, unless ENVIRONMENT_LOOKUP_ONLY is 1 (the look-up and the image's sampling alone:
// compose.frag, environment_emit.comp).
#ifndef ENVIRONMENT_LOOKUP_ONLY
#define ENVIRONMENT_LOOKUP_ONLY 0
#endif
#include "../shared/environment_data.h"

layout(std430, binding = kBindingEnvironment) readonly buffer SceneEnvironment { GpuEnvironment environment; };
// An image environment's texels and sampling tables (kUnitEnvironmentImage's layout).
layout(binding = kUnitEnvironmentImage) uniform sampler2D uEnvironmentImage;

bool hasEnvironment() {
    return environment.type.x != kEnvironmentNone;
}

bool hasEnvironmentImage() {
    return environment.type.x == kEnvironmentImage;
}

// The image texel whose solid angle holds unit direction `toward`.
ivec2 findEnvironmentTexel(vec3 toward) {
    ivec2 size = ivec2(environment.type.yz);
    vec2 uv = computeEnvironmentUv(toward, environment.image.xy);
    return min(ivec2(uv * vec2(size)), size - 1);
}

// Radiance arriving from unit direction `toward`; without an environment, the background
// (which lights nothing: callers ask only for what a ray that left the scene shows). An image's
// is its texel's (piecewise constant, as its pdf).
vec3 lookUpEnvironment(vec3 toward) {
    if (hasEnvironmentImage()) return texelFetch(uEnvironmentImage, findEnvironmentTexel(toward), 0).rgb;
    return evaluateEnvironment(environment, toward);
}

// The solid-angle pdf with which sampleEnvironmentImage draws unit direction `toward`.
float computeEnvironmentImagePdf(vec3 toward) {
    ivec2 texel = findEnvironmentTexel(toward);
    vec3 radiance = texelFetch(uEnvironmentImage, texel, 0).rgb;
    float weight = computeEnvironmentTexelWeight(radiance, uint(texel.y), environment.type.z);
    float sinTheta = length(toward.xz); // 1 - y^2 loses the digits near the poles
    return computeEnvironmentSolidAnglePdf(weight, environment.image.z, sinTheta);
}

// The first of `count` increasing CDF values (texels x = 0.. of row `row`, channel a; or
// row `row`'s r, the marginal) above u, by bisection; the last when rounding leaves u above all.
int findCdfEntry(int row, int count, bool marginal, float u) {
    int low = 0;
    int high = count - 1;
    while (low < high) {
        int mid = (low + high) / 2;
        vec4 t = texelFetch(uEnvironmentImage, ivec2(mid, row), 0);
        if ((marginal ? t.r : t.a) > u) {
            high = mid;
        } else {
            low = mid + 1;
        }
    }
    return low;
}

// Where u falls in CDF entry `index`'s step, in [0, 1).
float computeCdfOffset(int row, int index, bool marginal, float u) {
    vec4 t = texelFetch(uEnvironmentImage, ivec2(index, row), 0);
    float high = marginal ? t.r : t.a;
    float low = 0.0;
    if (index > 0) {
        vec4 p = texelFetch(uEnvironmentImage, ivec2(index - 1, row), 0);
        low = marginal ? p.r : p.a;
    }
    return high > low ? clamp((u - low) / (high - low), 0.0, 0.99999994) : 0.5;
}

struct EnvironmentSample {
    vec3 toward;   // unit, away from the receiver
    vec3 radiance; // W/(m^2 sr) from there
    float pdf;     // solid angle; 0: nothing drawn (a black image)
};

// A direction drawn from an image environment's pdf (docs/design.md "Environment"): a row by the
// marginal CDF from u.x, a texel in it by the row's conditional CDF from u.y, uniform in (u, v)
// inside the texel (scene/environment_image.cpp's sampleEnvironmentImage is its CPU twin).
EnvironmentSample sampleEnvironmentImage(vec2 u) {
    EnvironmentSample s;
    s.toward = vec3(0.0, 1.0, 0.0);
    s.radiance = vec3(0.0);
    s.pdf = 0.0;
    if (!(environment.image.z > 0.0)) return s;
    int width = int(environment.type.y);
    int height = int(environment.type.z);
    int row = findCdfEntry(height, height, true, u.x);
    float dv = computeCdfOffset(height, row, true, u.x);
    int column = findCdfEntry(row, width, false, u.y);
    float du = computeCdfOffset(row, column, false, u.y);
    vec2 uv = vec2((float(column) + du) / float(width), (float(row) + dv) / float(height));
    s.toward = computeEnvironmentDirection(uv, environment.image.xy);
    s.radiance = texelFetch(uEnvironmentImage, ivec2(column, row), 0).rgb;
    float weight = computeEnvironmentTexelWeight(s.radiance, uint(row), uint(height));
    s.pdf = computeEnvironmentSolidAnglePdf(weight, environment.image.z, sin(uv.y * kEnvironmentPi));
    return s;
}

#if !ENVIRONMENT_LOOKUP_ONLY
// Bounce slot of seedRandom for a pixel's environment samples.
const uint kEnvironmentSeedSlot = 0xfffffffbu;

// One environment sample at a surface point (normals as shadeEmitterSample's): a direction
// cosine-weighted about the shading normal from u.yz, kept where it leaves on the geometric
// normal's side and a ray reaches the open sky; BRDF x radiance x cos / (cos / pi).
vec3 shadeEnvironmentSample(vec3 u, vec3 positionW, vec3 n, vec3 shading, vec3 diffuse,
                            vec4 specular, vec3 wo, float rayFloorM) {
    vec3 dir = sampleCosine(shading, u.y, u.z);
    if (dot(n, dir) <= 0.0) return vec3(0.0);
    vec3 radiance = lookUpEnvironment(dir);
    if (all(equal(radiance, vec3(0.0)))) return vec3(0.0);
    float offset = computeRayOffset(positionW, rayFloorM);
    if (isRayBlocked(positionW + n * offset, dir, kNoHitDistance)) return vec3(0.0);
    return evaluateBrdf(diffuse, specular, shading, dir, wo) * radiance * kPi;
}

// BRDF x radiance x cos of light from unit direction `dir` at a surface point (normals as
// shadeEmitterSample's) where it leaves on the geometric normal's side and a ray reaches the open
// sky; 0 otherwise.
vec3 shadeEnvironmentDirection(vec3 dir, vec3 radiance, vec3 positionW, vec3 n, vec3 shading,
                               vec3 diffuse, vec4 specular, vec3 wo, float rayFloorM) {
    float cosTheta = dot(shading, dir);
    if (cosTheta <= 0.0 || dot(n, dir) <= 0.0 || all(equal(radiance, vec3(0.0)))) return vec3(0.0);
    float offset = computeRayOffset(positionW, rayFloorM);
    if (isRayBlocked(positionW + n * offset, dir, kNoHitDistance)) return vec3(0.0);
    return evaluateBrdf(diffuse, specular, shading, dir, wo) * radiance * cosTheta;
}

// One image environment sample for ispm's direct light: the direction drawn from the map's pdf
// (u.x < 1/2) or cosine-weighted about the shading normal, each with probability 1/2, weighed
// as their mixture (Veach's one-sample balance heuristic): f / (p_map / 2 + p_cos / 2). A sharp
// sun-like patch is found by the map, a broad sky over the hemisphere by the cosine, and no
// sample's weight exceeds 2 / p of either; one sample stands alone, so any area_samples works.
vec3 shadeEnvironmentImageSample(vec3 u, vec3 positionW, vec3 n, vec3 shading, vec3 diffuse,
                                 vec4 specular, vec3 wo, float rayFloorM) {
    vec3 dir;
    vec3 radiance;
    float mapPdf;
    if (u.x < 0.5) {
        EnvironmentSample s = sampleEnvironmentImage(u.yz);
        if (!(s.pdf > 0.0)) return vec3(0.0);
        dir = s.toward;
        radiance = s.radiance;
        // The drawn texel's own, not the one its direction finds again: on a texel's edge
        // rounding can find a black neighbour, whose 0 would leave p_cos / 2 alone.
        mapPdf = s.pdf;
    } else {
        dir = sampleCosine(shading, u.y, u.z);
        radiance = lookUpEnvironment(dir);
        mapPdf = computeEnvironmentImagePdf(dir);
    }
    float pdf = 0.5 * mapPdf + 0.5 * max(dot(shading, dir), 0.0) * kInvPi;
    if (!(pdf > 0.0)) return vec3(0.0);
    return shadeEnvironmentDirection(dir, radiance, positionW, n, shading, diffuse, specular, wo,
                                     rayFloorM) / pdf;
}

// Direct light from the environment at a surface point, the mean of `samples` samples (samples
// first.. of the sequence seeded by `seeds`).
vec3 computeEnvironmentRadiance(vec3 positionW, vec3 n, vec3 shading, vec3 diffuse,
                                vec4 specular, vec3 wo, float rayFloorM, uint first,
                                uint samples, uvec3 seeds) {
    if (!hasEnvironment() || samples == 0u) return vec3(0.0);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < samples; ++i) {
        vec3 u = computeEmitterNumbers(first + i, seeds);
        sum += hasEnvironmentImage()
                   ? shadeEnvironmentImageSample(u, positionW, n, shading, diffuse, specular, wo,
                                                 rayFloorM)
                   : shadeEnvironmentSample(u, positionW, n, shading, diffuse, specular, wo,
                                            rayFloorM);
    }
    return sum / float(samples);
}
#endif
