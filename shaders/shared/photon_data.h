// Photons as the GPU stores them, shared by C++ and GLSL: the bounce buffer (written by the emit
// pass through transform feedback), the result buffer (appended by the trace pass), the counters
// and the indirect arguments the passes hand each other without a CPU round trip.
#ifndef ISPM_PHOTON_DATA_H
#define ISPM_PHOTON_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// After the first bounce, at the surface the light camera saw. Interleaved transform-feedback
// varyings, in this order: outPositionDistance, outDirectionDensity, outPower.
struct BouncePhoton {
    vec4 positionDistance; // xyz world position (m); w = distance travelled from the light (m)
    vec4 directionDensity; // xyz unit outgoing direction; w = path density (1/m^2)
    vec4 power;            // rgb power (W) after the bounce; w = photon index (uint bits)
};
ISPM_STATIC_ASSERT_SIZE(BouncePhoton, 48);

// A photon landing on a diffuse or glossy surface, splatted onto the image.
struct ResultPhoton {
    vec4 positionDistance; // xyz hit position (m); w = distance travelled from the light (m)
    vec4 normalDensity;    // xyz unit normal on the side the photon arrived from; w = path density
    vec4 incoming;         // xyz unit direction of travel; w = uint bits: reflections before
                           // this hit (low 8 bits) | the light's index << 8
    vec4 power;            // rgb incoming power (W); w = splat radius (m), set by the density
                           // pass in every radius mode (0: not drawn; 0 before that pass)
};
ISPM_STATIC_ASSERT_SIZE(ResultPhoton, 64);

// Photons of one light in the last frame, counted on the GPU for reports.
struct LightPhotonCounters {
    uvec4 counts; // x = after the first bounce, y = stored, z = stored in view, w unused
};
ISPM_STATIC_ASSERT_SIZE(LightPhotonCounters, 16);

// Counters and indirect arguments in one buffer, so one bind serves every stage.
struct PhotonCounters {
    uvec4 bounce;          // x = bounce photons written (transform feedback query result)
    uvec4 result;          // x = result photons appended (may pass capacity), y = capacity,
                           // z = overflow (appends dropped), w = bounce capacity
    uvec4 traceDispatch;   // glDispatchComputeIndirect arguments (x, y, z)
    uvec4 splatDraw;       // glDrawArraysIndirect: count, instanceCount, first, baseInstance
    uvec4 densityDispatch; // glDispatchComputeIndirect over the stored result photons (xyz)
};
ISPM_STATIC_ASSERT_SIZE(PhotonCounters, 80);

ISPM_CONST uint kTraceGroupSize = 64u;
// Photons a lane of the trace takes in turn on a software renderer (photon_trace.comp): llvmpipe
// runs a group's lanes in step, eight to a SIMD vector, and a lane that takes its next photon as
// its path ends keeps busy while the others' paths go on. On a GPU one photon a lane keeps the
// most lanes in flight. Courtyard outside, 128x128, 25,000 photons, alternated runs: trace 7.4-9.6
// ms with one photon a lane, 6.1-6.9 with eight (32 and 128 no better).
ISPM_CONST uint kTracePhotonsPerLaneSoftware = 8u;

// Work groups of a trace over `photons` photons, `photonsPerLane` to a lane.
ISPM_INLINE uint computeTraceGroups(uint photons, uint photonsPerLane) {
    uint perGroup = kTraceGroupSize * photonsPerLane;
    return (photons + perGroup - 1u) / perGroup;
}

// A compute pass over `count` photons run in `slices` dispatches (the viewer draws a frame in
// slices across its UI frames): slice `slice` takes photons [x, y), as even as can be, in order.
// A slice's dispatch covers its share only (PhotonBuffers::dispatchSlice); one slice of one is
// the indirect dispatch over all.
ISPM_INLINE uvec2 computeSliceRange(uint count, uint slice, uint slices) {
    uint share = count / slices;
    uint extra = count % slices;
    uint begin = share * slice + min(slice, extra);
    return uvec2(begin, begin + share + (slice < extra ? 1u : 0u));
}
// Splat draw `draw` of `draws` over `count` instances, each of `indices` indices: the first uvec4
// of its indexed draw command (count, instanceCount, firstIndex, baseVertex; the next uvec4 holds
// baseInstance, 0: splat.vert finds the draw's first instance by computeSliceRange itself).
ISPM_INLINE uvec4 makeSplatDraw(uint indices, uint count, uint draw, uint draws) {
    uvec2 range = computeSliceRange(count, draw, draws);
    return uvec4(indices, range.y - range.x, 0u, 0u);
}
// Slices of the trace or the density pass in one frame, at most.
ISPM_CONST uint kMaxComputeSlices = 64u;
ISPM_CONST uint kMaxSplatPasses = 64u; // the splat_passes setting's range
// Draws one frame's splat may be split into: splat_passes, or more when the viewer draws a frame
// in slices across its UI frames (FrameRunner::beginFrame), each a share of the photons.
ISPM_CONST uint kMaxSplatDraws = 256u;
ISPM_CONST uint kSplatCubeVertices = 36u; // 12 triangles, indices into the cube's 8 corners
ISPM_CONST uint kSplatCubeCorners = 8u;
// A splat pass's glDrawElementsIndirect command {count, instanceCount, firstIndex, baseVertex,
// baseInstance} takes two uvec4s of the draw buffer (the second holds baseInstance).
ISPM_CONST uint kSplatDrawUvec4s = 2u;

// Binding points (storage buffers), after the BVH's.
ISPM_CONST int kBindingBouncePhotons = 11;
ISPM_CONST int kBindingResultPhotons = 12;
ISPM_CONST int kBindingPhotonCounters = 13;
ISPM_CONST int kBindingSplatDraws = 14;    // indexed draw commands, kSplatDrawUvec4s per splat pass
ISPM_CONST int kBindingLightCounts = 19;   // uvec4 per light (LightPhotonCounters)
ISPM_CONST int kBindingEmissionGrids = 20; // uvec4 per grid: first photon, view, light, 0
ISPM_CONST uint kReflectionBits = 8u;      // ResultPhoton.incoming.w: reflections, then light
ISPM_CONST int kBindingCausticList = 28;   // splat.vert: the caustic photons' draw command
                                           // (kSplatDrawUvec4s), then their indices (the tail of
                                           // photon_density.comp's table buffer)
ISPM_CONST int kBindingDensityCells = 17;  // photon_density.comp's hashed grid (kDensitySlotUints
                                           // a slot)
ISPM_CONST int kBindingDiscList = 33;      // splat.vert and photon_prepare.comp, radius_mode
                                           // density: the count of the discs drawn (x of a
                                           // uvec4), then their photons' indices (in
                                           // photon_density.comp's table buffer)

// Splat shapes (setting splat_shape, checked against the table in frame_settings.cpp), and the
// indices a photon's instance draws: the box's 12 triangles, the disc's 2 (over the box's
// corners 0-3). The draw commands carry the count of the frame's shape (photon_prepare.comp).
ISPM_CONST uint kSplatShapeDisc = 0u;
ISPM_CONST uint kSplatShapeBox = 1u;
ISPM_CONST uint kSplatDiscIndices = 6u;
ISPM_INLINE uint getSplatIndexCount(uint shape) {
    return shape == kSplatShapeBox ? kSplatCubeVertices : kSplatDiscIndices;
}

// Which result photons a splat draw or the gather takes (SplatParams::photons,
// GatherParams::photons). In radius_mode density a caustic photon (focused by a mirror, glass or a
// glossy lobe since its last diffuse bounce: path density above 1) has discs sized by the
// caustic photons around it alone (photon_density.comp); the caustic photons are splatted apart,
// at the image's resolution and left out of the filter, so that their sharp shapes survive, and
// the rest at `splat_resolution`, filtered.
ISPM_CONST uint kSplatAllPhotons = 0u;
ISPM_CONST uint kSplatDiffusePhotons = 1u;
ISPM_CONST uint kSplatCausticPhotons = 2u;

ISPM_INLINE bool isCausticPhoton(float pathDensity) {
    return pathDensity > 1.0f;
}

ISPM_INLINE bool isSplatTaken(uint which, float pathDensity) {
    if (which == kSplatAllPhotons) return true;
    return isCausticPhoton(pathDensity) == (which == kSplatCausticPhotons);
}

// Splat radius modes (setting radius_mode, checked against the table in splat_pass.cpp).
ISPM_CONST uint kRadiusTravel = 0u;
ISPM_CONST uint kRadiusPathDensity = 1u;
ISPM_CONST uint kRadiusDensity = 2u;

// The settings of the modes travel and path_density (a member of DensityParams: std140).
struct TravelRadii {
    float radiusMinM; // radius_min (times radius_scale)
    float radiusMaxM; // radius_max (times radius_scale)
    float distMinM;   // dist_min: travel up to which a photon takes radius_min
    float distMaxM;   // dist_max: travel from which a photon takes radius_max
};
ISPM_STATIC_ASSERT_SIZE(TravelRadii, 16);

// Radii of the modes travel and path_density. travel (the thesis): from radius_min at dist_min
// to radius_max at dist_max, linear in the distance the photon travelled between. path_density
// (McGuire and Luebke 2009), from the path alone: radius_max for a photon whose path never
// focused (path density 1: diffuse bounces only), divided by the square root of the path density,
// so focused photons splat smaller, never below radius_min.
ISPM_INLINE float computeTravelRadius(float travelledM, float pathDensity, TravelRadii radii,
                                      uint mode) {
    if (mode == kRadiusPathDensity)
        return max(radii.radiusMinM, radii.radiusMaxM / sqrt(max(pathDensity, 1.0f)));
    float s = clamp((travelledM - radii.distMinM) / max(radii.distMaxM - radii.distMinM, 1e-9f),
                    0.0f, 1.0f);
    return mix(radii.radiusMinM, radii.radiusMaxM, s);
}

// Local photon density: result photons are counted in hashed grids of cubic cells, one grid per
// level, each level's cells twice the size of the one below.
ISPM_CONST uint kDensityLevels = 8u;
ISPM_CONST uint kDensityProbes = 32u; // open addressing gives up after this many slots
// A slot: key, photon count, power, unused, then the in-plane extent of its photons (see
// photon_density.comp).
ISPM_CONST uint kDensitySlotUints = 8u;

// photon_prepare.comp's stages: before tracing (bounce count -> trace dispatch, result counters
// reset), before splatting (result count -> splat draws and the density dispatch), and in
// radius_mode density after the density pass (its list of discs -> splat draws: the photons in
// view that keep a disc of their own, caustic ones apart, so that a merged cell's collapsed
// photons and the photons outside the view draw no instance).
ISPM_CONST uint kPrepareStageBeforeTrace = 0u;
ISPM_CONST uint kPrepareStageBeforeSplat = 1u;
ISPM_CONST uint kPrepareStageDiscDraws = 2u;

// Parameters of photon_prepare.comp (std140, at kBindingPassParams).
struct PrepareParams {
    uint resultCapacity;  // result photons the buffer holds
    uint bounceCapacity;  // bounce photons the buffer holds
    uint stage;           // kPrepareStage*
    uint splatDraws;      // draws the splat is split into
    uint splatIndexCount; // indices a photon's splat draws (getSplatIndexCount)
    uint photonsPerLane;  // photons a lane of the trace takes (computeTraceGroups)
    uint padding0;
    uint padding1;
};
ISPM_STATIC_ASSERT_SIZE(PrepareParams, 32);

// Parameters of photon_trace.comp (std140, at kBindingPassParams).
struct TraceParams {
    uint bounces;
    uint seed;         // the frame's
    uint rngGenerator; // kRngPcg ...
    uint rngMode;      // kRngFixed ...
    float rayOffsetM;  // ray offset off the surface a photon leaves
    uint slice;        // this slice (computeSliceRange)
    uint slices;
    uint padding0;
};
ISPM_STATIC_ASSERT_SIZE(TraceParams, 32);

// The first bounce's Russian roulette (setting first_bounce): on the surface's albedo, so that
// absorbed photons end there (the thesis's), or among the lobes alone, by their share of the
// albedo, the photon's power times it (none is absorbed where the surface reflects at all: at the
// same count more of them go on, each carrying the surface's colour).
ISPM_CONST uint kFirstBounceRoulette = 0u;
ISPM_CONST uint kFirstBounceWeighted = 1u;

// Parameters of photon_emit.geom for one light view's grid (std140, at kBindingPassParams).
struct EmitParams {
    uint lightView;         // the light G-buffer's layer
    uint firstPhoton;       // global index of the grid's first photon
    uvec2 gridPhotons;      // photons across and down the view
    uint seed;              // the frame's
    uint rngGenerator;      // kRngPcg ...
    uint lightResolutionPx; // light G-buffer size (texels a side)
    uint firstBounce;       // kFirstBounce*
};
ISPM_STATIC_ASSERT_SIZE(EmitParams, 32);

// Parameters of the splat pass, splat.vert and splat.frag (std140, at kBindingPassParams); one
// block per splat_passes draw, bound by range.
struct SplatParams {
    uint clipLines; // 1: the discs have clip lines (splat_clip)
    uint shape;     // kSplatShape*
    uint draw;      // this draw
    uint drawCount;
    float squash;          // thickness along the normal / radius
    int pixelsPerBufferPx; // image pixels per splat-buffer pixel along an axis
    // Where the buffer's pixel (0, 0) lies in the target drawn (SplatPass::computeTargetOffset).
    ivec2 targetOffsetPx;
    uint photons;  // which photons the draw takes (kSplat*Photons)
    uint discList; // 1: its instances are the density pass's list of discs (kBindingDiscList)
    uint padding0;
    uint padding1;
};
ISPM_STATIC_ASSERT_SIZE(SplatParams, 48);

// photon_density.comp's stages: count photons into the grid, then radii and clip lines; in the
// travel modes the cull (travel radii against the view frustum, in-view counts), after the sum of
// each light's photons and power with widen_strong.
ISPM_CONST uint kDensityStageCount = 0u;
ISPM_CONST uint kDensityStageRadius = 1u;
ISPM_CONST uint kDensityStageTravelCull = 2u;
ISPM_CONST uint kDensityStageTravelPower = 3u;
// splat_merge: photons whose discs would lie almost on top of each other are drawn as one
// (photon_density.comp): the radius stage sums them per merge cell, this stage makes one of them
// the cell's disc and collapses the others.
ISPM_CONST uint kDensityStageMerge = 4u;
// Merge cells share the density table with the counting cells, keyed at levels past this (their
// sums), and past twice this (their radii).
ISPM_CONST uint kDensityMergeLevelOffset = 32u;
// widen_strong: a travel-mode disc at most this many times wider than its travel radius.
ISPM_CONST float kMaxWidening = 2.0f;

// The radius stage's order (splat_clip on): photon_order.comp sorts the stored photons by the
// Morton code of the cell that holds each in a grid of 2^kOrderAxisBits cells a side over the
// scene's bounds (a counting sort: count per cell, one group's prefix sum, scatter), so that
// neighbouring invocations take neighbouring photons: their clip queries walk the same BVH
// nodes and their table lookups the same cells, which a SIMD renderer runs together (llvmpipe
// runs a group's lanes in step). In the density cells buffer the counts follow the table (one
// clear for both), the order the caustic list.
ISPM_CONST uint kOrderAxisBits = 5u;
ISPM_CONST uint kOrderCells = 1u << (3u * kOrderAxisBits);
ISPM_CONST uint kOrderScanGroupSize = 1024u; // the scan's one group: kOrderCells / 32 invocations
ISPM_CONST uint kOrderStageCount = 0u;
ISPM_CONST uint kOrderStageScan = 1u;
ISPM_CONST uint kOrderStageScatter = 2u;

// Parameters of photon_order.comp (std140, at kBindingPassParams).
struct OrderParams {
    vec3 loW;       // the scene bounds' low corner
    uint countsAt;  // the counts' first uint in the density cells
    vec3 cellsPerM; // grid cells per metre along each axis
    uint orderAt;   // the order's first uint in the density cells
};
ISPM_STATIC_ASSERT_SIZE(OrderParams, 32);

// Bit i of v (i < kOrderAxisBits) at bit 3i.
ISPM_INLINE uint spreadOrderBits(uint v) {
    uint spread = 0u;
    for (uint i = 0u; i < kOrderAxisBits; ++i)
        spread |= ((v >> i) & 1u) << (3u * i);
    return spread;
}

// The order's cell of a photon at `position`: its grid cell (outside the bounds, the nearest),
// numbered in Morton order.
ISPM_INLINE uint computeOrderCell(vec3 position, OrderParams params) {
    const float last = float((1u << kOrderAxisBits) - 1u);
    vec3 at = clamp((position - params.loW) * params.cellsPerM, vec3(0.0f), vec3(last));
    uvec3 c = uvec3(at);
    return spreadOrderBits(c.x) | (spreadOrderBits(c.y) << 1u) | (spreadOrderBits(c.z) << 2u);
}

// Parameters of photon_density.comp (std140, at kBindingPassParams).
struct DensityParams {
    float finestCellM;        // the finest level's cell size
    float neighbours;         // neighbours k a radius spans
    float radiusMinM;         // radius at least
    float radiusMaxM;         // radius at most
    float radiusScale;        // radius_scale
    float rayOffsetM;         // ray offset off a surface
    float travelRadiusFactor; // radius at most this times the travel (0: off)
    float mergeCellPerRadius; // merge cell / radius (splat_merge, 0: off)
    uint stage;               // kDensityStage*, as the program's DENSITY_STAGE
    uint slotMask;            // table slots - 1 (a power of two)
    uint spreadStrong;        // 1: measure a photon against its neighbours only
    uint radiusMode;          // kRadius*
    TravelRadii travel;       // travel modes
    uint slice;               // this slice (computeSliceRange)
    uint slices;
    // The radius stage's photon order's first uint in the cells (photon_order.comp), 0: index
    // order.
    uint orderAt;
    uint causticListAt; // the caustic list's first uint in the cells (its draw command)
    float squash;       // surface_ends: the splat's
    // radius_mode density: the disc list's first uint in the cells (its count, then 3 unused
    // uints, then the indices).
    uint discListAt;
    uint padding0;
    uint padding1;
};
ISPM_STATIC_ASSERT_SIZE(DensityParams, 96);

ISPM_NAMESPACE_END

#endif
