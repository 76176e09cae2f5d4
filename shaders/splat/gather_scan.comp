// Tiled gather: each tile's list starts where the lists of the tiles before it end (an exclusive
// prefix sum of the counts, one workgroup, each invocation summing a run of tiles); the header
// gets the total, which sizes the list buffer, and the fill cursors start at 0.
#include "shared/gather_data.h"
#include "shared/scene_data.h"

layout(local_size_x = kGatherScanGroupSize) in;

layout(std430, binding = kBindingGatherTiles) buffer TileBuffer {
    uvec4 header;
    GatherTile tiles[];
};
layout(std140, binding = kBindingPassParams) uniform GatherParamsBlock { GatherParams params; };

shared uint sRunTotals[kGatherScanGroupSize];

void main() {
    uint count = params.tileCount;
    uint run = (count + kGatherScanGroupSize - 1u) / kGatherScanGroupSize;
    uint begin = gl_LocalInvocationID.x * run;
    uint end = min(begin + run, count);
    uint sum = 0u;
    for (uint i = begin; i < end; ++i) sum += tiles[i].counts.x;
    sRunTotals[gl_LocalInvocationID.x] = sum;
    barrier();
    // The runs before this one, summed by each invocation (256 adds: cheaper than a tree on a
    // CPU rasteriser, and a small share of the pass on a GPU).
    uint offset = 0u;
    for (uint i = 0u; i < gl_LocalInvocationID.x; ++i) offset += sRunTotals[i];
    for (uint i = begin; i < end; ++i) {
        tiles[i].counts.y = offset;
        tiles[i].counts.z = 0u;
        offset += tiles[i].counts.x;
    }
    if (gl_LocalInvocationID.x == kGatherScanGroupSize - 1u) header = uvec4(offset, 0u, 0u, 0u);
}
