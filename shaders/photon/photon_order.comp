// The stored photons in spatial order for the density pass's radius stage (shared/photon_data.h,
// kOrderAxisBits): a counting sort by the Morton code of each photon's grid cell. Stage 0 counts
// the photons per cell, stage 1 (one group) turns the counts into each cell's first slot, stage 2
// writes each photon's index into its cell's next slot. Photons of one cell come in any order.
#include "shared/scene_data.h"
#include "shared/photon_data.h"

#if ORDER_STAGE == 1
layout(local_size_x = kOrderScanGroupSize) in;
#else
layout(local_size_x = kTraceGroupSize) in;
#endif

layout(std430, binding = kBindingResultPhotons) readonly buffer ResultBuffer { ResultPhoton photons[]; };
layout(std430, binding = kBindingPhotonCounters) readonly buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingDensityCells) buffer DensityCells { uint cells[]; };
layout(std140, binding = kBindingPassParams) uniform OrderParamsBlock { OrderParams params; };

const uint kStage = ORDER_STAGE;
const uint kCellsPerInvocation = kOrderCells / kOrderScanGroupSize;

shared uint gSums[kOrderScanGroupSize];

void main() {
    uint counts = params.countsAt;
    if (kStage == kOrderStageScan) {
        // Each invocation's run of cells, the runs' exclusive prefix sum (Hillis and Steele),
        // then each cell's first slot.
        uint local = gl_LocalInvocationID.x;
        uint first = counts + local * kCellsPerInvocation;
        uint sum = 0u;
        for (uint i = 0u; i < kCellsPerInvocation; ++i) sum += cells[first + i];
        gSums[local] = sum;
        barrier();
        for (uint step = 1u; step < kOrderScanGroupSize; step *= 2u) {
            uint add = local >= step ? gSums[local - step] : 0u;
            barrier();
            gSums[local] += add;
            barrier();
        }
        uint slot = gSums[local] - sum;
        for (uint i = 0u; i < kCellsPerInvocation; ++i) {
            uint count = cells[first + i];
            cells[first + i] = slot;
            slot += count;
        }
        return;
    }
    uint index = gl_GlobalInvocationID.x;
    if (index >= counters.splatDraw.y) return;
    uint cell = computeOrderCell(photons[index].positionDistance.xyz, params);
    if (kStage == kOrderStageCount) {
        atomicAdd(cells[counts + cell], 1u);
        return;
    }
    cells[params.orderAt + atomicAdd(cells[counts + cell], 1u)] = index;
}
