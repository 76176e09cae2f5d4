// Ends one sample of the light tracer: adds the sample's splat buffer (reference/light_trace.comp)
// to the accumulation image as one sample (rgb sum, count), clears it for the next, and adds what
// light paths cannot reach: emission and background seen through a jittered camera ray (the
// path tracer's first vertex, reference.comp): an emitter's front (or either side of a two-sided
// one), the environment, or the background.
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/bvh.glsl"
#include "shared/photon_scatter.h"
#include "shared/light_trace_data.h"
#define ENVIRONMENT_LOOKUP_ONLY 1
#include "lib/environment.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform image2D uAccumulation;

layout(std140, binding = kBindingPassParams) uniform LightTraceParamsBlock { LightTraceParams params; };
layout(std430, binding = kBindingLightSplat) buffer LightSplat { float splat[]; };

vec3 traceEmission(vec2 pixel) {
    vec3 dir = normalize(computeEyeToNear(pixel));
    RayHit hit;
    if (!traceRay(frame.cameraPosW, dir, kNoHitDistance, hit)) {
        return hasEnvironment() ? lookUpEnvironment(dir) : frame.backgroundRadiance;
    }
    vec4 emission = materials[triangles[hit.triangle].w].emission;
    bool front = dot(computeHitNormal(hit), dir) < 0.0;
    return front || emission.w > 0.5 ? emission.rgb : vec3(0.0);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uAccumulation);
    if (any(greaterThanEqual(pixel, size))) return;
    uint index = 3u * uint(pixel.y * size.x + pixel.x);
    vec3 light = vec3(splat[index], splat[index + 1u], splat[index + 2u]);
    splat[index] = 0.0;
    splat[index + 1u] = 0.0;
    splat[index + 2u] = 0.0;
    uint rng = seedRandom(uint(pixel.y * size.x + pixel.x), params.sampleIndex, ~params.seed);
    vec2 jitter = vec2(nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
    vec3 seen = traceEmission(vec2(pixel) + jitter);
    vec4 sum = imageLoad(uAccumulation, pixel);
    imageStore(uAccumulation, pixel, sum + vec4(light + seen, 1.0));
}
