// Between passes, on the GPU: after emission, turn the bounce count into the trace dispatch and
// reset the result counters; after tracing, split the result photons into the splat passes' draw
// commands (glDrawElementsIndirect: count, instanceCount, firstIndex, baseVertex, baseInstance).
#include "shared/photon_data.h"
#include "shared/scene_data.h"

layout(local_size_x = 1) in;
layout(std430, binding = kBindingPhotonCounters) buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatDraws) writeonly buffer SplatDrawBuffer { uvec4 splatDraws[]; };

layout(std140, binding = kBindingPassParams) uniform PrepareParamsBlock { PrepareParams params; };

void main() {
    if (params.control.z == kPrepareStageBeforeTrace) {
        uint bounced = min(counters.bounce.x, params.control.y);
        counters.bounce.x = bounced;
        counters.traceDispatch = uvec4(computeTraceGroups(bounced, params.splat.y), 1u, 1u, 0u);
        counters.result = uvec4(0u, params.control.x, 0u, params.control.y);
        return;
    }
    uint stored = min(counters.result.x, counters.result.y);
    counters.splatDraw = uvec4(params.splat.x, stored, 0u, 0u);
    counters.densityDispatch = uvec4((stored + kTraceGroupSize - 1u) / kTraceGroupSize, 1u, 1u, 0u);
    for (uint p = 0u; p < params.control.w; ++p) {
        uint begin = stored * p / params.control.w;
        uint end = stored * (p + 1u) / params.control.w;
        // baseInstance is left 0: the vertex stage adds the pass's first photon itself.
        splatDraws[kSplatDrawUvec4s * p] = uvec4(params.splat.x, end - begin, 0u, 0u);
        splatDraws[kSplatDrawUvec4s * p + 1u] = uvec4(0u);
    }
}
