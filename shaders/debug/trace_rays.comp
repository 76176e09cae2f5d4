// Closest-hit queries for a batch of rays through the scene's BVH (lib/bvh.glsl): the GPU side of
// tests against the CPU traversal, and a building block for debug tools such as the viewer's
// picking. One invocation per ray; results come back in ray order.
#include "lib/scene_buffers.glsl"
#include "lib/bvh.glsl"

// Debug and test bindings, above the product's storage bindings (0..14 in shared/*.h), so a
// query can run with every product buffer still bound.
const int kBindingDebugRays = 15;    // DebugRay per ray
const int kBindingDebugResults = 16; // uvec4 per ray
// One ray per invocation; 64 is a whole number of SIMD groups on current GPUs (32 or 64 wide).
const uint kTraceRaysGroupSize = 64u;

layout(local_size_x = kTraceRaysGroupSize) in;

struct DebugRay {
    vec4 originTMax; // xyz world-space origin, w = tMax (world-space distance)
    vec4 direction;  // xyz world-space unit direction, w unused
};

layout(std430, binding = kBindingDebugRays) readonly buffer DebugRays { DebugRay debugRays[]; };
// x = 1 on a hit else 0, y = global triangle, z = instance, w = floatBitsToUint(t); on a miss
// y, z are 0 and t is the ray's tMax.
layout(std430, binding = kBindingDebugResults) writeonly buffer DebugResults {
    uvec4 debugResults[];
};

layout(location = 0) uniform uint uRayCount; // the last group runs past the end of the rays

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= uRayCount) return;
    DebugRay ray = debugRays[index];
    RayHit hit;
    bool found = traceRay(ray.originTMax.xyz, ray.direction.xyz, ray.originTMax.w, hit);
    debugResults[index] =
        uvec4(found ? 1u : 0u, hit.triangle, hit.instance, floatBitsToUint(hit.t));
}
