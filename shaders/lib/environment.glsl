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

// Direct light from the environment at a surface point, the mean of `samples` samples (samples
// first.. of the sequence seeded by `seeds`).
vec3 computeEnvironmentRadiance(vec3 positionW, vec3 n, vec3 shading, vec3 diffuse,
                                vec4 specular, vec3 wo, float rayFloorM, uint first,
                                uint samples, uvec3 seeds) {
    if (!hasEnvironment() || samples == 0u) return vec3(0.0);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < samples; ++i) {
        sum += shadeEnvironmentSample(computeEmitterNumbers(first + i, seeds), positionW, n,
                                      shading, diffuse, specular, wo, rayFloorM);
    }
    return sum / float(samples);
}
#endif
