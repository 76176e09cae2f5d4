// The environment's light (shared/environment_data.h, docs/design.md "Environment"): what it
// sends along a direction, and its direct light at a surface point from cosine-weighted
// directions, each with a ray through the BVH to the open sky. Needs scene_buffers.glsl,
// bvh.glsl, brdf.glsl and emitters.glsl (the sample sequence) included before, unless
// ENVIRONMENT_LOOKUP_ONLY is 1 (lookUpEnvironment alone: compose.frag).
#ifndef ENVIRONMENT_LOOKUP_ONLY
#define ENVIRONMENT_LOOKUP_ONLY 0
#endif
#include "../shared/environment_data.h"

layout(std430, binding = kBindingEnvironment) readonly buffer SceneEnvironment { GpuEnvironment environment; };

bool hasEnvironment() {
    return environment.type.x != kEnvironmentNone;
}

// Radiance arriving from unit direction `toward`; without an environment, the background
// (which lights nothing: callers ask only for what a ray that left the scene shows).
vec3 lookUpEnvironment(vec3 toward) {
    return evaluateEnvironment(environment, toward);
}

#if !ENVIRONMENT_LOOKUP_ONLY
// Bounce slot of seedRandom for a pixel's environment samples.
const uint kEnvironmentSeedSlot = 0xfffffffbu;

// Direct light from the environment at a surface point (n faces the viewer, wo points to it),
// the mean of `samples` cosine-weighted directions (samples first.. of the sequence seeded by
// `seeds`): BRDF x radiance x cos / (cos / pi) where the ray reaches the open sky.
vec3 computeEnvironmentRadiance(vec3 positionW, vec3 n, vec3 diffuse, vec4 specular, vec3 wo,
                                float rayFloorM, uint first, uint samples, uvec3 seeds) {
    if (!hasEnvironment() || samples == 0u) return vec3(0.0);
    float offset = computeRayOffset(positionW, rayFloorM);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < samples; ++i) {
        vec3 u = computeEmitterNumbers(first + i, seeds);
        vec3 dir = sampleCosine(n, u.y, u.z);
        vec3 radiance = lookUpEnvironment(dir);
        if (all(equal(radiance, vec3(0.0)))) continue;
        if (isRayBlocked(positionW + n * offset, dir, kNoHitDistance)) continue;
        sum += evaluateBrdf(diffuse, specular, n, dir, wo) * radiance * kPi;
    }
    return sum / float(samples);
}
#endif
