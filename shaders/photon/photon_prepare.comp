// Between passes, on the GPU: after emission, turn the bounce count into the trace dispatch and
// reset the result counters; after tracing, split the result photons into the splat passes' draw
// commands (glDrawElementsIndirect: count, instanceCount, firstIndex, baseVertex, baseInstance);
// in radius_mode density, after the density pass, split its list of discs into them instead.
#include "shared/photon_data.h"
#include "shared/scene_data.h"

layout(local_size_x = 1) in;
layout(std430, binding = kBindingPhotonCounters) buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatDraws) writeonly buffer SplatDrawBuffer { uvec4 splatDraws[]; };

layout(std140, binding = kBindingPassParams) uniform PrepareParamsBlock { PrepareParams params; };
#ifndef DISC_DRAWS
#define DISC_DRAWS 0
#endif
#if DISC_DRAWS // the program of stage kPrepareStageDiscDraws: the list is bound then
layout(std430, binding = kBindingDiscList) readonly buffer DiscList { uvec4 discCount; };
#endif

void main() {
#if DISC_DRAWS
    // The same indices a splat as the stage before gave the draws.
    for (uint p = 0u; p < params.splatDraws; ++p)
        splatDraws[kSplatDrawUvec4s * p] = makeSplatDraw(counters.splatDraw.x, discCount.x, p, params.splatDraws);
    return;
#endif
    if (params.stage == kPrepareStageBeforeTrace) {
        uint bounced = min(counters.bounce.x, params.bounceCapacity);
        counters.bounce.x = bounced;
        counters.traceDispatch = uvec4(computeTraceGroups(bounced, params.photonsPerLane), 1u, 1u, 0u);
        counters.result = uvec4(0u, params.resultCapacity, 0u, params.bounceCapacity);
        return;
    }
    uint stored = min(counters.result.x, counters.result.y);
    counters.splatDraw = uvec4(params.splatIndexCount, stored, 0u, 0u);
    counters.densityDispatch = uvec4((stored + kTraceGroupSize - 1u) / kTraceGroupSize, 1u, 1u, 0u);
    for (uint p = 0u; p < params.splatDraws; ++p) {
        splatDraws[kSplatDrawUvec4s * p] = makeSplatDraw(params.splatIndexCount, stored, p, params.splatDraws);
        splatDraws[kSplatDrawUvec4s * p + 1u] = uvec4(0u);
    }
}
