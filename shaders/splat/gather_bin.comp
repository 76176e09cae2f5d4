// Tiled gather, binning: each stored result photon finds the screen tiles its splat's box can
// touch (the 8 corners of its extents in the plane and radius x squash along the normal,
// projected; the whole buffer when a corner lies behind the camera) and counts itself in each
// (COUNT), or, after gather_scan.comp placed the tiles' lists, writes its index into each (FILL).
// Photons with radius 0 (culled by the density pass) go nowhere.
#include "lib/frame_constants.glsl"
#include "shared/gather_data.h"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"

layout(local_size_x = kGatherBinGroupSize) in;

layout(std430, binding = kBindingResultPhotons) readonly buffer ResultBuffer { ResultPhoton photons[]; };
layout(std430, binding = kBindingPhotonCounters) readonly buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatClip) readonly buffer SplatClip { vec4 splatClip[]; };
layout(std430, binding = kBindingGatherTiles) buffer TileBuffer {
    uvec4 header;
    GatherTile tiles[];
};
#ifdef FILL
layout(std430, binding = kBindingGatherList) writeonly buffer ListBuffer { uint list[]; };
#endif
layout(std140, binding = kBindingPassParams) uniform GatherParamsBlock { GatherParams params; };

#include "lib/splat_kernel.glsl"

// A pixel's margin round the projected box: the buffer pixel's centre samples a G-buffer point
// up to half an image pixel away (getBlockGBufferPixel), and round-off.
const float kMarginPx = 1.0;

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= min(counters.result.x, counters.result.y)) return;
    SplatShape shape = loadSplatShape(id, params.clipLines);
    if (!(shape.radius > 0.0) || !isSplatTaken(params.photons, photons[id].normalDensity.w)) return;
    vec3 n = photons[id].normalDensity.xyz;
    vec3 t;
    vec3 b;
    buildSplatBasis(n, t, b);
    vec3 p = photons[id].positionDistance.xyz;
    vec2 size = vec2(params.bufferSizePx);
    vec2 lo = vec2(1e30);
    vec2 hi = vec2(-1e30);
    bool behind = false;
    float thickness = shape.radius * params.squash;
    for (int c = 0; c < 8; ++c) {
        float alongT = (c & 1) != 0 ? shape.extent.x : -shape.extent.y;
        float alongB = (c & 2) != 0 ? shape.extent.z : -shape.extent.w;
        float alongN = (c & 4) != 0 ? thickness : -thickness;
        vec3 corner = p + t * alongT + b * alongB + n * alongN;
        vec4 clip = toBlockClip(frame.clipFromWorld * vec4(corner, 1.0), int(params.pixelsPerBufferPx));
        if (clip.w <= 0.0) {
            behind = true;
            break;
        }
        vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * size;
        lo = min(lo, pixel);
        hi = max(hi, pixel);
    }
    if (behind) {
        lo = vec2(0.0);
        hi = size;
    }
    lo -= kMarginPx;
    hi += kMarginPx;
    if (hi.x < 0.0 || hi.y < 0.0 || lo.x > size.x || lo.y > size.y) return;
    ivec2 last = ivec2(params.tiles) - 1;
    ivec2 first = clamp(ivec2(floor(max(lo, vec2(0.0)) / float(kGatherTilePx))), ivec2(0), last);
    ivec2 end = clamp(ivec2(floor(min(hi, size) / float(kGatherTilePx))), ivec2(0), last);
    for (int y = first.y; y <= end.y; ++y) {
        for (int x = first.x; x <= end.x; ++x) {
            uint tile = uint(y) * params.tiles.x + uint(x);
#ifdef FILL
            uint slot = atomicAdd(tiles[tile].counts.z, 1u);
            list[tiles[tile].counts.y + slot] = id;
#else
            atomicAdd(tiles[tile].counts.x, 1u);
#endif
        }
    }
}
