// Splat radii from the local density of result photons. Stage 0 counts every stored photon, and
// sums its power, into a hashed grid of cubic cells at each level (cell size h0 * 2^level).
// Stage 1 finds, per photon, the finest level whose 2x2x2 block of cells around it holds at least
// k photons and takes the local power density E = power / area from that block (the area its
// photons span on their plane, at most the (2h)^2 a plane through it cuts; in one frame the
// others' mean power times the count, so that a strong photon does not set the density it is
// measured against). The photon's disc gets the radius at
// which its own power is 1/k of what lands there, r = sqrt(k P / (pi E)): with equal powers, the
// disc that holds k photons; a photon k times stronger than its neighbours (importance sampling's
// floor, another light) spreads sqrt(k) times wider instead of making a bright spot. Times
// radius_scale, clamped.
//
// In the travel modes stage 2 gives each photon its travel (or path-density) radius, 0 where that
// disc cannot reach the view, and counts the others in view. With WIDEN_STRONG 1 (widen_strong)
// stage 3 runs first and sums each light's stored photons and their power; stage 2 then draws a
// photon stronger than its light's mean sqrt(power / mean) times wider (at most kMaxWidening),
// as the density radii spread a photon stronger than its neighbours: importance sampling's floor
// sends photons with up to 1 / (1 - importance) times the power they would carry unaimed, and a
// whole disc of that power is a blotch. A weaker photon keeps its radius.
//
// Stage 1 also culls photons whose disc lies outside the view frustum (radius 0: the splat skips
// them). With SURFACE_ENDS 1 (surface_ends, without clip lines) stage 1 or 2 divides each
// photon's power by the share of its disc that the viewer G-buffer shows a surface for. With
// MERGE_DISCS 1 (splat_merge) stage 1 adds each photon to its merge cell, and stage 4 draws each
// cell's photons as one disc (mergePhoton). Stage 1, and with MERGE_DISCS stage 4, list the
// photons that keep a disc of their own (appendDisc), for photon_prepare.comp to turn into the
// splat's draws. With CLIP_DISCS 1 (splat_clip) stage 1
// or 2 finds the lines where surfaces cut each disc in view (shared/splat_clip.h): the in-plane
// rays of the clip, met against the triangles of one BVH box query around the disc.
#include "lib/constants.glsl"
#define ISPM_BVH_BOX_VISITOR
// Its box queries see alpha-tested cards whole (a disc that crosses a leaf card's gap is clipped
// there as by the whole card), and it has no storage block to spare for texture coordinates.
#define BVH_ALPHA_TEST 0
#include "lib/scene_buffers.glsl"
#include "lib/bvh.glsl"
#include "lib/frame_constants.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"
#include "lib/photon_lights.glsl"
#if SURFACE_ENDS
#include "lib/viewer_gbuffer.glsl"
#endif

layout(local_size_x = kTraceGroupSize) in;

layout(std430, binding = kBindingResultPhotons) buffer ResultBuffer { ResultPhoton photons[]; };
layout(std430, binding = kBindingPhotonCounters) buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatClip) writeonly buffer SplatClip { vec4 splatClip[]; };
// Slot s at S = kDensitySlotUints s: key at S (0 = empty), photon count at S + 1, power (float
// bits) at S + 2; at S + 4 .. S + 7 the extent of its photons along the two axes of the plane
// their facing is closest to, as fixed-point fractions of the cell (kExtentOne = the whole
// cell): M - min u, max u, M - min v, max v, all kept by atomicMax from a cleared table.
// At params.causticListAt (after the table's slots, and with splat_clip the order's counts): the
// caustic photons in view, for their own splat draw: its command (kSplatDrawUvec4s uvec4s, the
// instance count added here), then their indices; with splat_clip at params.orderAt the order.
layout(std430, binding = kBindingDensityCells) buffer DensityCells { uint cells[]; };

layout(std140, binding = kBindingPassParams) uniform DensityParamsBlock { DensityParams params; };

// The stage this program runs (kDensityStage*): one program per stage (PhotonDensityPass), so
// no stage pays for another's code, which llvmpipe would run under a mask (it runs both sides
// of every branch, and every loop at least once).
const uint kStage = DENSITY_STAGE;
const bool kClipDiscs = CLIP_DISCS != 0;
const bool kWidenStrong = WIDEN_STRONG != 0;
const bool kMergeDiscs = MERGE_DISCS != 0; // splat_merge above 0

// The clip rays run this far above the surface, as a fraction of the radius: steps lower than
// that do not clip a disc, walls do.
const float kClipLift = 0.02;

// Whether a sphere lies entirely outside one of the view frustum's planes (Gribb and Hartmann:
// the planes are sums and differences of the rows of clipFromWorld).
bool isOutsideView(vec3 centre, float radius) {
    mat4 m = transpose(frame.clipFromWorld);
    for (int i = 0; i < 6; ++i) {
        vec4 plane = m[3] + ((i & 1) == 0 ? 1.0 : -1.0) * m[i / 2];
        if (dot(plane.xyz, centre) + plane.w < -radius * length(plane.xyz)) return true;
    }
    return false;
}

// Photons are counted apart by the side they face (the major axis of the normal and its sign):
// the two faces of a thin wall, or a floor and the wall it meets, do not share a density. And
// apart by their path (kCausticMap): photons focused by mirrors, glass or a glossy lobe since
// their last diffuse bounce (path density above 1) form a caustic map of their own, as in
// Jensen's photon maps, so a caustic's discs hold its own photons' neighbours, small where
// they crowd, and the diffuse light around it keeps the radii of its own density.
const uint kCausticMap = 8u;
uint getFacing(vec3 n, float pathDensity) {
    vec3 a = abs(n);
    uint axis = a.x >= a.y && a.x >= a.z ? 0u : (a.y >= a.z ? 1u : 2u);
    return 2u * axis + (n[axis] < 0.0 ? 1u : 0u) + (isCausticPhoton(pathDensity) ? kCausticMap : 0u);
}

uint hashCell(ivec3 c, uint level, uint facing) {
    return hashPcg(uint(c.x) ^ hashPcg(uint(c.y) ^ hashPcg(uint(c.z) ^ hashPcg(level * 16u + facing))));
}

// Float addition by compare-and-swap (core GLSL has no float atomics).
void addFloat(uint index, float value) {
    uint seen = cells[index];
    for (;;) {
        uint previous = atomicCompSwap(cells[index], seen, floatBitsToUint(uintBitsToFloat(seen) + value));
        if (previous == seen) return;
        seen = previous;
    }
}

const float kExtentOne = 16777216.0; // 2^24: a whole cell in the extent words

// radius_mode density: photon `index` keeps a disc of its own (not collapsed into its merge cell's,
// not a caustic photon: those have their list): the splat draws it.
void appendDisc(uint index) {
    uint at = atomicAdd(cells[params.discListAt], 1u);
    cells[params.discListAt + 4u + at] = index;
}


void appendCausticPhoton(uint index) {
    uint list = params.causticListAt;
    uint at = atomicAdd(cells[list + 1u], 1u);
    cells[list + 4u * kSplatDrawUvec4s + at] = index;
}

float getCellSize(uint level) { return params.finestCellM * exp2(float(level)); }

// The two axes of the plane a facing is closest to.
ivec2 getPlaneAxes(uint facing) {
    int axis = int((facing % kCausticMap) / 2u);
    return ivec2((axis + 1) % 3, (axis + 2) % 3);
}

// The table slot of cell c (at `level`, facing `facing`): its first uint. Open addressing from
// the cell's hash, the key the hash | 1 (0: empty); with `insert` an empty slot is claimed for
// it. kNoSlot where the table does not hold the cell (find) or has no room for it within
// kDensityProbes slots.
const uint kNoSlot = 0xffffffffu;
uint findSlot(ivec3 c, uint level, uint facing, bool insert) {
    uint h = hashCell(c, level, facing);
    uint key = h | 1u;
    uint slot = hashPcg(h) & params.slotMask;
    for (uint i = 0u; i < kDensityProbes; ++i) {
        uint at = kDensitySlotUints * slot;
        uint previous = insert ? atomicCompSwap(cells[at], 0u, key) : cells[at];
        if (previous == key || (insert && previous == 0u)) return at;
        if (previous == 0u) return kNoSlot;
        slot = (slot + 1u) & params.slotMask;
    }
    return kNoSlot;
}

void insertCell(vec3 p, uint level, uint facing, float power) {
    float size = getCellSize(level);
    ivec3 c = ivec3(floor(p / size));
    uint at = findSlot(c, level, facing, true);
    if (at == kNoSlot) return;
    atomicAdd(cells[at + 1u], 1u);
    addFloat(at + 2u, power);
    ivec2 axes = getPlaneAxes(facing);
    vec3 within = clamp(p / size - vec3(c), 0.0, 1.0) * kExtentOne;
    uvec2 q = uvec2(within[axes.x], within[axes.y]);
    atomicMax(cells[at + 4u], uint(kExtentOne) - q.x);
    atomicMax(cells[at + 5u], q.x);
    atomicMax(cells[at + 6u], uint(kExtentOne) - q.y);
    atomicMax(cells[at + 7u], q.y);
}

// splat_merge: a disc of radius r is merged with the others in its merge cell, the cell of the
// density grid's coarsest level whose side is at most scales.w r (none when even the finest is
// larger: -1), so that merged discs differ in radius by less than 2x.
int computeMergeLevel(float radius) {
    float cells = params.mergeCellPerRadius * radius / params.finestCellM;
    return cells >= 1.0 ? min(int(floor(log2(cells))), int(kDensityMergeLevelOffset) - 1) : -1;
}

// A merge cell's two slots in the density table (keyed apart from the counting cells): its sums
// (part 0) and its radii (part 1). Part 0 at S: key, the cell's disc (its highest photon index
// + 1, by atomicMax) at S + 1, the summed power (RGB, float bits) at S + 2 .. S + 4, the
// positions weighted by power at S + 5 .. S + 7. Part 1: the squared radii weighted by power at
// S + 1. As findSlot, at the merge levels.
uint findMergeSlot(vec3 p, int level, uint facing, uint part, bool insert) {
    return findSlot(ivec3(floor(p / getCellSize(uint(level)))),
                    uint(level) + (part + 1u) * kDensityMergeLevelOffset, facing, insert);
}

// Adds the photon to its merge cell; false where the table has no room (it stays a disc of its
// own).
bool addToMerge(uint index, vec3 p, float radius, int level, uint facing) {
    uint sums = findMergeSlot(p, level, facing, 0u, true);
    uint radii = sums == kNoSlot ? kNoSlot : findMergeSlot(p, level, facing, 1u, true);
    if (radii == kNoSlot) return false;
    atomicMax(cells[sums + 1u], index + 1u);
    vec3 power = photons[index].power.rgb;
    float weight = computeMean(power);
    for (uint i = 0u; i < 3u; ++i) {
        addFloat(sums + 2u + i, power[i]);
        addFloat(sums + 5u + i, p[i] * weight);
    }
    addFloat(radii + 1u, radius * radius * weight);
    return true;
}

// A block of cells: photon count, power, and where its photons lie along the plane's axes
// (world coordinates, lo and hi).
struct Block {
    float count;
    float power;
    vec2 lo;
    vec2 hi;
};

// Adds cell c's photons to `block`.
void addCell(inout Block block, ivec3 c, uint level, uint facing) {
    uint at = findSlot(c, level, facing, false);
    if (at == kNoSlot) return;
    block.count += float(cells[at + 1u]);
    block.power += uintBitsToFloat(cells[at + 2u]);
    float size = getCellSize(level);
    ivec2 axes = getPlaneAxes(facing);
    vec2 origin = vec2(float(c[axes.x]), float(c[axes.y])) * size;
    float scale = size / kExtentOne;
    vec2 lo = origin + (kExtentOne - vec2(cells[at + 4u], cells[at + 6u])) * scale;
    vec2 hi = origin + vec2(cells[at + 5u], cells[at + 7u]) * scale;
    block.lo = min(block.lo, lo);
    block.hi = max(block.hi, hi);
}

// The 2x2x2 cells nearest to p (a cube of side 2h around it).
Block sumBlock(vec3 p, uint level, uint facing) {
    ivec3 first = ivec3(floor(p / getCellSize(level) - 0.5));
    Block block = Block(0.0, 0.0, vec2(3.4e38), vec2(-3.4e38));
    for (int i = 0; i < 8; ++i) addCell(block, first + ivec3(i & 1, (i >> 1) & 1, i >> 2), level, facing);
    return block;
}

// The area of surface the block's photons stand for. A plane through the block cuts about
// side^2; a surface narrower than the block (a door jamb, a wall's end, a ledge) or one that
// ends inside it cuts less, and counting side^2 there makes the density too low and the discs
// too wide (light blurred along a jamb). So each axis of the plane takes the span of the
// photons, widened by (n + 1) / (n - 1) (n uniform points span (n - 1) / (n + 1) of their
// interval on average), at most the side. Below kMinSpanCount photons the span says little and
// the side stands; a span is at least kMinSpanShare of the side.
const float kMinSpanCount = 24.0;
const float kMinSpanShare = 1.0 / 16.0;
float computeBlockArea(Block block, float side) {
    if (block.count < kMinSpanCount) return side * side;
    vec2 span = (block.hi - block.lo) * ((block.count + 1.0) / (block.count - 1.0));
    span = clamp(span, vec2(kMinSpanShare * side), vec2(side));
    return span.x * span.y;
}

// The photon's power as one number: the mean over RGB, so saturated colours count.
float getPhotonPower(uint index) { return max(computeMean(photons[index].power.rgb), 1e-30); }

// Ray origins: above the surface by kClipLift of the radius (at least a few ray epsilons), and
// just beneath it.
vec3 getAboveOrigin(vec3 p, vec3 n, float radius) { return p + n * max(4.0 * computeRayOffset(p, params.rayOffsetM), kClipLift * radius); }
vec3 getBeneathOrigin(vec3 p, vec3 n) { return p - n * (4.0 * computeRayOffset(p, params.rayOffsetM)); }

// The disc being clipped (one per invocation): its plane's basis and the two ray origins (0
// above, 1 beneath). Per origin and ray the nearest surface met so far: its distance along the
// ray, and its unit normal in the plane's coordinates. Rays 0-3 and 4-7 sit in the lanes of
// vec4s, so that a triangle meets four rays at once (kClipRays is 8: splat_clip.h).
vec3 gDiscT;
vec3 gDiscB;
vec3 gDiscN;
vec3 gAbove;
vec3 gBeneath;
float gLift; // the above origin's height over the beneath origin's
struct RayQuad {
    vec4 nearest;
    vec4 normalT;
    vec4 normalB;
};
RayQuad gAboveLo;
RayQuad gAboveHi;
RayQuad gBeneathLo;
RayQuad gBeneathHi;
vec4 gRayT[2];
vec4 gRayB[2];

// Whether a triangle with corner heights d (above a plane along gDiscN) crosses the plane: a
// corner at height 0 counts as above, so a triangle in the plane does not.
bool crossesPlane(vec3 d) { return min(d.x, min(d.y, d.z)) < 0.0 && max(d.x, max(d.y, d.z)) >= 0.0; }

// The segment where a plane through `origin` cuts a triangle that crosses it (corner heights d),
// a-b in the plane's coordinates around origin.
void cutTriangle(vec3 origin, vec3 p0, vec3 p1, vec3 p2, vec3 d, out vec2 a, out vec2 b) {
    bvec3 above = greaterThanEqual(d, vec3(0.0));
    // The corner alone on its side, and the two across.
    bool lone0 = above.y == above.z;
    bool lone1 = !lone0 && above.x == above.z;
    vec3 lone = lone0 ? p0 : (lone1 ? p1 : p2);
    float dLone = lone0 ? d.x : (lone1 ? d.y : d.z);
    vec3 x = lone0 ? p1 : p0;
    float dx = lone0 ? d.y : d.x;
    vec3 y = lone0 || lone1 ? p2 : p1;
    float dy = lone0 || lone1 ? d.z : d.y;
    vec3 qa = lone + (x - lone) * (dLone / (dLone - dx)) - origin;
    vec3 qb = lone + (y - lone) * (dLone / (dLone - dy)) - origin;
    a = vec2(dot(qa, gDiscT), dot(qa, gDiscB));
    b = vec2(dot(qb, gDiscT), dot(qb, gDiscB));
}

// Four rays (directions in the lanes of rayT, rayB) against the segment a-b.
void hitRays(vec2 a, vec2 e, vec4 rayT, vec4 rayB, vec2 normal2, inout RayQuad quad) {
    vec4 det = rayT * e.y - rayB * e.x;
    vec4 inverse = 1.0 / mix(det, vec4(1.0), equal(det, vec4(0.0)));
    vec4 s = vec4(a.x * e.y - a.y * e.x) * inverse;
    vec4 u = (a.x * rayB - a.y * rayT) * inverse;
    bvec4 hit = bvec4(uvec4(notEqual(det, vec4(0.0))) * uvec4(greaterThan(s, vec4(0.0))) *
                      uvec4(lessThan(s, quad.nearest)) * uvec4(greaterThanEqual(u, vec4(0.0))) *
                      uvec4(lessThanEqual(u, vec4(1.0))));
    quad.nearest = mix(quad.nearest, s, hit);
    quad.normalT = mix(quad.normalT, vec4(normal2.x), hit);
    quad.normalB = mix(quad.normalB, vec4(normal2.y), hit);
}

// The clip rays run in the photon's plane, so a triangle meets a ray where the segment its
// plane cuts does: one plane section per origin and a 2D test per ray, for every triangle near
// the disc (the BVH walked once per photon, not once per ray).
void visitBoxTriangle(vec3 p0, vec3 p1, vec3 p2) {
    // Corner heights above the beneath origin's plane; the above origin's plane lies gLift higher.
    vec3 beneath = vec3(dot(p0 - gBeneath, gDiscN), dot(p1 - gBeneath, gDiscN), dot(p2 - gBeneath, gDiscN));
    vec3 above = beneath - vec3(gLift);
    bool cutsAbove = crossesPlane(above);
    bool cutsBeneath = crossesPlane(beneath);
    if (!cutsAbove && !cutsBeneath) return; // most often the photon's own surface
    vec3 normal = normalize(cross(p1 - p0, p2 - p0));
    vec2 normal2 = vec2(dot(normal, gDiscT), dot(normal, gDiscB));
    vec2 a;
    vec2 b;
    if (cutsAbove) {
        cutTriangle(gAbove, p0, p1, p2, above, a, b);
        hitRays(a, b - a, gRayT[0], gRayB[0], normal2, gAboveLo);
        hitRays(a, b - a, gRayT[1], gRayB[1], normal2, gAboveHi);
    }
    if (cutsBeneath) {
        cutTriangle(gBeneath, p0, p1, p2, beneath, a, b);
        hitRays(a, b - a, gRayT[0], gRayB[0], normal2, gBeneathLo);
        hitRays(a, b - a, gRayT[1], gRayB[1], normal2, gBeneathHi);
    }
}

// The lines packed as the splat takes them (loadSplatShape): those running past the disc both
// ways first, then the bounded ones, then zero poles.
void writeClip(uint index, vec2 poles[kClipRays], uint wedges[kClipRays], float radius) {
    vec2 packedPoles[kClipRays];
    uint packedWedges[kClipRays];
    uint lines = 0u;
    for (uint pass = 0u; pass < 2u; ++pass) {
        for (uint i = 0u; i < kClipRays; ++i) {
            if (dot(poles[i], poles[i]) <= 0.0 || (wedges[i] == kWedgeOpenBoth) != (pass == 0u)) continue;
            packedPoles[lines] = poles[i];
            packedWedges[lines] = wedges[i];
            ++lines;
        }
    }
    for (uint i = lines; i < kClipRays; ++i) {
        packedPoles[i] = vec2(0.0);
        packedWedges[i] = kWedgeOpenBoth;
    }
    for (uint i = 0u; i < kClipRays / 2u; ++i) {
        splatClip[index * kClipVec4s + i] = vec4(packedPoles[2u * i], packedPoles[2u * i + 1u]);
    }
    splatClip[index * kClipVec4s + kClipRays / 2u] = computeClipExtent(poles, wedges, radius);
    for (uint i = 0u; i < kClipRays / 4u; ++i) {
        splatClip[index * kClipVec4s + kClipRays / 2u + 1u + i] =
            vec4(uvec4(packedWedges[4u * i], packedWedges[4u * i + 1u], packedWedges[4u * i + 2u],
                       packedWedges[4u * i + 3u]));
    }
}

// Rays above the surface find the walls it meets (concave edges); rays just beneath it, inside
// the solid it bounds, find where it ends (convex edges: a wall's end, a door jamb, a roof's
// rim), beyond which the disc would fall into the air. Per direction the nearer line counts.
void clipDisc(uint index, vec3 p, vec3 n, float radius) {
    gDiscN = n;
    buildSplatBasis(n, gDiscT, gDiscB);
    gAbove = getAboveOrigin(p, n, radius);
    gBeneath = getBeneathOrigin(p, n);
    gLift = dot(gAbove - gBeneath, n);
    for (uint i = 0u; i < 4u; ++i) {
        for (uint half_ = 0u; half_ < 2u; ++half_) {
            vec2 ray2 = getClipDirection(4u * half_ + i);
            gRayT[half_][i] = ray2.x;
            gRayB[half_][i] = ray2.y;
        }
    }
    RayQuad none = RayQuad(vec4(radius), vec4(0.0), vec4(0.0));
    gAboveLo = none;
    gAboveHi = none;
    gBeneathLo = none;
    gBeneathHi = none;
    // The box both origins' rays sweep.
    vec3 sweep = (abs(gDiscT) + abs(gDiscB)) * radius;
    queryBox(min(gAbove, gBeneath) - sweep, max(gAbove, gBeneath) + sweep);
    vec2 poles[kClipRays];
    float hitsM[kClipRays];
    for (uint i = 0u; i < kClipRays; ++i) {
        RayQuad above = i < 4u ? gAboveLo : gAboveHi;
        RayQuad beneath = i < 4u ? gBeneathLo : gBeneathHi;
        uint lane = i % 4u;
        // Per direction the nearer surface: a wall above, or the surface's own end beneath.
        bool useBeneath = beneath.nearest[lane] < above.nearest[lane];
        float t = useBeneath ? beneath.nearest[lane] : above.nearest[lane];
        vec2 normal2 = useBeneath ? vec2(beneath.normalT[lane], beneath.normalB[lane])
                                  : vec2(above.normalT[lane], above.normalB[lane]);
        vec2 ray2 = getClipDirection(i);
        poles[i] = t < radius ? computeClipPole(ray2 * t, normal2, ray2) : vec2(0.0);
        hitsM[i] = t; // the radius where nothing was met (RayQuad none)
    }
    removeRepeatedLines(poles, radius);
    uint wedges[kClipRays];
    findLineWedges(poles, hitsM, radius, wedges);
    writeClip(index, poles, wedges, radius);
}

// A hash of a photon's position: photons are stored in another order each run, and a choice
// made per photon must follow the photon, not its index.
uint hashPosition(vec3 p) {
    uvec3 bits = floatBitsToUint(p);
    return hashPcg(bits.x ^ hashPcg(bits.y ^ hashPcg(bits.z)));
}

#if SURFACE_ENDS
// surface_ends: whether the viewer sees past the point q of the disc round photon (p, n): the
// pixel that shows q shows the background or a surface farther from the eye than q, so no
// surface holds q and the splat has nowhere to put light there (a wall's top against the sky,
// its side against the yard, the opening of its door). Where the pixel shows the photon's own
// surface (facing its way, within the splat's squash x radius of its plane: what the splat
// accepts), a nearer surface (which may hide q's surface: unknown) or q lies outside the image,
// the surface is taken to go on.
bool isSeenPast(vec3 q, vec3 p, vec3 n, float radius) {
    ivec2 pixel;
    if (!findViewerPixel(q, pixel)) return false;
    vec4 shown = texelFetch(uPosition, pixel, 0);
    if (shown.w < 0.5) return true;
    bool onPlane = dot(texelFetch(uNormal, pixel, 0).xyz, n) > 0.0 &&
                   abs(dot(shown.xyz - p, n)) <= params.squash * radius;
    if (onPlane) return false;
    vec3 eye = frame.cameraPosW;
    return distance(eye, shown.xyz) > distance(eye, q);
}

// The share of the disc's kernel that lies where a surface may hold it (isSeenPast), from its
// points on two rings of kSurfaceRingPoints: at 0.366 r and 0.707 r, the middles (by kernel
// mass) of the inner and outer halves of the kernel (2 s^2 - s^4 of it lies within s r: 1/4 and
// 3/4 there), the second ring turned half a step against the first, both by a hash of the
// photon's position. At least kMinKeptMass, as splat_clip's kept mass. Dividing the photon's
// power by it keeps that power on the surfaces the viewer sees: a disc reaching past a wall's
// edge into the air lost it there, and the wall's rim came out dark.
const uint kSurfaceRingPoints = 4u;
float computeSurfaceShare(vec3 p, vec3 n, float radius) {
    vec3 t;
    vec3 b;
    buildSplatBasis(n, t, b);
    float turn = float(hashPosition(p)) * (2.0 * kPi / 4294967296.0);
    const float kRings[2] = float[2](0.366, 0.707);
    float onSurface = 0.0;
    for (uint ring = 0u; ring < 2u; ++ring) {
        for (uint i = 0u; i < kSurfaceRingPoints; ++i) {
            float angle = turn + (float(i) + 0.5 * float(ring)) * (2.0 * kPi / float(kSurfaceRingPoints));
            vec3 q = p + kRings[ring] * radius * (cos(angle) * t + sin(angle) * b);
            onSurface += isSeenPast(q, p, n, radius) ? 0.0 : 1.0;
        }
    }
    return max(onSurface / float(2u * kSurfaceRingPoints), kMinKeptMass);
}
#endif

// widen_strong: light l's stored photons at cells[2 l], their power (float bits) at cells[2 l + 1],
// of one photon in kPowerSampleStride: the mean of thousands to a few per cent, without every
// photon of a light waiting on one word (the float add is a compare-and-swap loop: 40,000 photons
// of the Cornell box's one light took 4-19 ms, 1 in 8 of them well under 1). Chosen by a hash of
// its position, not its index: photons are stored in another order each run, and the same
// photons must set the same mean.
const uint kPowerSampleStride = 8u;
void addLightPower(uint index) {
    if (hashPosition(photons[index].positionDistance.xyz) % kPowerSampleStride != 0u) return;
    uint light = unpackLight(photons[index].incoming.w);
    atomicAdd(cells[2u * light], 1u);
    addFloat(2u * light + 1u, getPhotonPower(index));
}

// How many times wider than its travel radius the photon's disc is drawn: sqrt(power / mean) of
// its light's photons, 1 to kMaxWidening.
float computeWidening(uint index) {
    uint light = unpackLight(photons[index].incoming.w);
    float count = float(cells[2u * light]);
    float mean = count > 0.0 ? uintBitsToFloat(cells[2u * light + 1u]) / count : 0.0;
    return mean > 0.0 ? clamp(sqrt(getPhotonPower(index) / mean), 1.0, kMaxWidening) : 1.0;
}

// Travel modes: the photon's radius from its travel or path (computeTravelRadius), 0 (not drawn)
// when its disc cannot reach the view; the others count as in view.
void setTravelRadius(uint index) {
    float radius = computeTravelRadius(photons[index].positionDistance.w, photons[index].normalDensity.w,
                                       params.travel, params.radiusMode);
    if (kWidenStrong) radius *= computeWidening(index);
    if (isOutsideView(photons[index].positionDistance.xyz, radius)) {
        photons[index].power.w = 0.0;
        return;
    }
    countPhoton(unpackLight(photons[index].incoming.w), 2);
    photons[index].power.w = radius;
#if SURFACE_ENDS
    photons[index].power.rgb /=
        computeSurfaceShare(photons[index].positionDistance.xyz, photons[index].normalDensity.xyz, radius);
#endif
    if (kClipDiscs) clipDisc(index, photons[index].positionDistance.xyz, photons[index].normalDensity.xyz, radius);
}

// Merge stage: the photon with its merge cell's highest index becomes the cell's disc: the
// cell's power at its power-weighted centre, of the power-weighted RMS of their radii (the
// spread of their discs), its own normal and incoming direction; the others draw nothing. As in
// the radius stage, a photon without a merge cell keeps its disc.
void mergePhoton(uint index) {
    float radius = photons[index].power.w;
    if (!(radius > 0.0) || isCausticPhoton(photons[index].normalDensity.w)) return;
    int level = computeMergeLevel(radius);
    if (level < 0) return;
    vec3 p = photons[index].positionDistance.xyz;
    vec3 n = photons[index].normalDensity.xyz;
    uint facing = getFacing(n, photons[index].normalDensity.w);
    uint sums = findMergeSlot(p, level, facing, 0u, false);
    uint radii = sums == kNoSlot ? kNoSlot : findMergeSlot(p, level, facing, 1u, false);
    if (radii != kNoSlot) {
        if (cells[sums + 1u] != index + 1u) {
            photons[index].power = vec4(0.0); // its power is the cell's disc's now
            return;
        }
        vec3 power = uintBitsToFloat(uvec3(cells[sums + 2u], cells[sums + 3u], cells[sums + 4u]));
        vec3 weighted = uintBitsToFloat(uvec3(cells[sums + 5u], cells[sums + 6u], cells[sums + 7u]));
        float weight = max(computeMean(power), 1e-30);
        p = weighted / weight;
        radius = sqrt(uintBitsToFloat(cells[radii + 1u]) / weight);
        photons[index].power = vec4(power, radius);
        photons[index].positionDistance.xyz = p;
        // The cell's disc (a photon without a cell was listed by the radius stage).
        appendDisc(index);
    }
    if (kClipDiscs) clipDisc(index, p, n, radius);
}

void main() {
    uvec2 range = computeSliceRange(counters.splatDraw.y, params.slice, params.slices);
    uint at = range.x + gl_GlobalInvocationID.x;
    if (at >= range.y) return;
    // The radius stage takes the photons in spatial order where photon_order.comp made one.
    uint index = (kStage == kDensityStageRadius || kStage == kDensityStageMerge) && params.orderAt != 0u
                     ? cells[params.orderAt + at]
                     : at;
    if (kStage == kDensityStageTravelPower) {
        addLightPower(index);
        return;
    }
    if (kStage == kDensityStageTravelCull) {
        setTravelRadius(index);
        return;
    }
    if (kStage == kDensityStageMerge) {
        mergePhoton(index);
        return;
    }
    vec3 p = photons[index].positionDistance.xyz;
    float power = getPhotonPower(index);
    uint facing = getFacing(photons[index].normalDensity.xyz, photons[index].normalDensity.w);
    if (kStage == kDensityStageCount) {
        for (uint level = 0u; level < kDensityLevels; ++level) insertCell(p, level, facing, power);
        return;
    }
    // Counts grow with the level: binary search for the finest one that holds k, the coarsest
    // when none does (summed only then: most photons find theirs below it).
    float k = params.neighbours;
    uint lo = 0u;
    uint hi = kDensityLevels - 1u;
    Block block;
    bool found = false;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        Block b = sumBlock(p, mid, facing);
        if (b.count >= k) {
            hi = mid;
            block = b;
            found = true;
        } else {
            lo = mid + 1u;
        }
    }
    if (!found) block = sumBlock(p, hi, facing);
    float side = 2.0 * getCellSize(hi);
    float area = computeBlockArea(block, side);
    // One frame: the others' mean power stands for every photon of the block, since a photon
    // much stronger than its neighbours (a low pdf of the importance map, reached after a few
    // bounces) would otherwise set the density it is measured against and stay a bright spot.
    // Averaged frames count it in: their noise falls with the frames, the wider disc's blur not.
    float others = block.count > 1.5 ? (block.power - power) / (block.count - 1.0) : power;
    bool spreadStrong = params.spreadStrong != 0u;
    float powerDensity = spreadStrong ? max(others, 1e-30) * max(block.count, 1.0) / area
                                      : max(block.power, power) / area;
    float radius = sqrt(k * power / (kPi * powerDensity)) * params.radiusScale;
    // Never wider than the coarsest block: a lone photon in an empty scene stays finite.
    radius = min(radius, 2.0 * getCellSize(kDensityLevels - 1u));
    // While frames are averaged: light from a surface d away varies over about d (a wall's foot);
    // the finest cell keeps a photon that travelled almost nothing from a point-sized disc.
    if (params.travelRadiusFactor > 0.0) {
        float travel = photons[index].positionDistance.w;
        radius = min(radius, max(params.travelRadiusFactor * travel, getCellSize(0u)));
    }
    radius = clamp(radius, params.radiusMinM, params.radiusMaxM);
    if (isOutsideView(p, radius)) {
        photons[index].power.w = 0.0;
        return;
    }
    countPhoton(unpackLight(photons[index].incoming.w), 2);
    photons[index].power.w = radius;
#if SURFACE_ENDS
    photons[index].power.rgb /= computeSurfaceShare(p, photons[index].normalDensity.xyz, radius);
#endif
    if (isCausticPhoton(photons[index].normalDensity.w)) {
        appendCausticPhoton(index);
    } else {
        // A merged photon's disc is listed and clipped by the merge stage, if it is its cell's.
        int level = kMergeDiscs ? computeMergeLevel(radius) : -1;
        if (level >= 0 && addToMerge(index, p, radius, level, facing)) return;
        appendDisc(index);
    }
    if (kClipDiscs) clipDisc(index, p, photons[index].normalDensity.xyz, radius);
}
