// Closest-hit queries for a batch of rays through the scene's BVH (lib/bvh.glsl): the GPU side of
// tests against the CPU traversal, and a building block for debug tools such as the viewer's
// picking. One invocation per ray; results come back in ray order.
#include "lib/scene_buffers.glsl"
#include "lib/bvh.glsl"
#include "shared/debug_data.h"

layout(local_size_x = kTraceRaysGroupSize) in;

layout(std430, binding = kBindingDebugRays) readonly buffer DebugRays { DebugRay debugRays[]; };
layout(std430, binding = kBindingDebugResults) writeonly buffer DebugResults {
    uvec4 debugResults[];
};

layout(std140, binding = kBindingPassParams) uniform TraceRaysParamsBlock { TraceRaysParams params; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= params.rayCount) return;
    DebugRay ray = debugRays[index];
    RayHit hit;
    bool found = traceRay(ray.originTMax.xyz, ray.direction.xyz, ray.originTMax.w, hit);
    debugResults[index] =
        uvec4(found ? 1u : 0u, hit.triangle, hit.instance, floatBitsToUint(hit.t));
}
