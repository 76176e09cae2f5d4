// Between passes, on the GPU: after emission, turn the bounce count into the trace dispatch and
// reset the result counters; after tracing, split the result photons into the splat passes' draw
// commands (glDrawElementsIndirect: count, instanceCount, firstIndex, baseVertex, baseInstance).
#include "shared/photon_data.h"

layout(local_size_x = 1) in;
layout(std430, binding = kBindingPhotonCounters) buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatDraws) writeonly buffer SplatDrawBuffer { uvec4 splatDraws[]; };

layout(location = 0) uniform uvec2 uCapacity; // x = result capacity, y = bounce capacity
layout(location = 1) uniform uint uStage;     // 0: before tracing, 1: before splatting
layout(location = 2) uniform uint uSplatPasses;

void main() {
    if (uStage == 0u) {
        uint bounced = min(counters.bounce.x, uCapacity.y);
        counters.bounce.x = bounced;
        counters.traceDispatch = uvec4((bounced + kTraceGroupSize - 1u) / kTraceGroupSize, 1u, 1u, 0u);
        counters.result = uvec4(0u, uCapacity.x, 0u, uCapacity.y);
        return;
    }
    uint stored = min(counters.result.x, counters.result.y);
    counters.splatDraw = uvec4(kSplatCubeVertices, stored, 0u, 0u);
    counters.densityDispatch = uvec4((stored + kTraceGroupSize - 1u) / kTraceGroupSize, 1u, 1u, 0u);
    counters.clipDispatch = uvec4(0u, 1u, 1u, 0u); // the density pass's stage 1 grows it
    for (uint p = 0u; p < uSplatPasses; ++p) {
        uint begin = stored * p / uSplatPasses;
        uint end = stored * (p + 1u) / uSplatPasses;
        // baseInstance is left 0: the vertex stage adds the pass's first photon itself.
        splatDraws[kSplatDrawUvec4s * p] = uvec4(kSplatCubeVertices, end - begin, 0u, 0u);
        splatDraws[kSplatDrawUvec4s * p + 1u] = uvec4(0u);
    }
}
