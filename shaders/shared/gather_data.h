// The tiled gather (splat_mode gather, SplatPass): result photons binned into screen tiles of the
// splat buffer by the projected box of their splat, then each pixel sums the photons of its tile
// with the splat's kernel, normal and clip tests (lib/splat_kernel.glsl), as splat.frag does for
// the fragments a splat covers. Shared by C++ and GLSL.
#ifndef ISPM_GATHER_DATA_H
#define ISPM_GATHER_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

ISPM_CONST uint kSplatModeRaster = 0u; // instanced splats (splat_shape disc or box)
ISPM_CONST uint kSplatModeGather = 1u; // the tiled gather

ISPM_CONST int kBindingGatherTiles = 25; // GatherTiles: header, then a uvec4 per tile
ISPM_CONST int kBindingGatherList = 26;  // uint photon index per (tile, photon) pair, by tile
ISPM_CONST int kImageGatherOutput = 0;   // the splat buffer (rgba32f), written by gather.comp

ISPM_CONST uint kGatherTilePx = 8u; // a tile is 8 x 8 splat-buffer pixels, one workgroup
ISPM_CONST uint kGatherBinGroupSize = 64u;
ISPM_CONST uint kGatherScanGroupSize = 256u;
// Photons a tile's workgroup stages in shared memory at a time (10 vec4 each: 20 KiB of the 32
// KiB every GL 4.3 implementation has).
ISPM_CONST uint kGatherBatch = 64u;

// Per tile: x = photons binned into it, y = first slot in the list, z = slots filled so far
// (gather_bin.comp FILL), w unused. The header's x is the list's length (gather_scan.comp).
struct GatherTile {
    uvec4 counts;
};
ISPM_STATIC_ASSERT_SIZE(GatherTile, 16);

// Parameters of gather_bin.comp, gather_scan.comp and gather.comp (std140, at
// kBindingPassParams).
struct GatherParams {
    uvec2 tiles; // tiles across and down
    uint tileCount;
    uint clipLines;         // 1: clip lines (splat_clip)
    uvec2 bufferSizePx;     // the splat buffer's
    uint pixelsPerBufferPx; // image pixels per buffer pixel along an axis
    uint photons;           // which photons it takes (kSplat*Photons, shared/photon_data.h)
    float squash;           // thickness along the normal / radius
    float padding0;
    float padding1;
    float padding2;
};
ISPM_STATIC_ASSERT_SIZE(GatherParams, 48);

ISPM_NAMESPACE_END

#endif
