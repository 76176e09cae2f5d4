// Ray traversal of the two-level BVH (shared/bvh_data.h): a stack over the top level's instance
// boxes, and for each instance leaf a stack over its mesh's bottom level, in object space. The
// object-space direction is not renormalised, so hit distances stay world-space distances.
// Needs scene_buffers.glsl included before. Alpha-tested materials (GpuMaterial::surface.x) are
// cut out where their texture says so, for every ray. BVH_ALPHA_TEST 0 compiles the test out:
// for scenes without such materials (GpuScene::getRayDefines), and in a shader with no storage
// block to spare for the texture coordinates (llvmpipe allows 16), which then sees them whole.
#include "../shared/bvh_data.h"
#ifndef BVH_ALPHA_TEST
#define BVH_ALPHA_TEST 1
#endif
#if BVH_ALPHA_TEST
// (The loader takes a file once, where it is first named: a shader under BVH_ALPHA_TEST 0 that
// reads textures includes scene_textures.glsl before this file.)
#include "scene_textures.glsl"
#endif

layout(std430, binding = kBindingBlasNodes) readonly buffer BlasNodes { GpuBvhNode blasNodes[]; };
layout(std430, binding = kBindingBlasTriangleOrder) readonly buffer BlasOrder { uint blasTriangleOrder[]; };
layout(std430, binding = kBindingTlasNodes) readonly buffer TlasNodes { GpuBvhNode tlasNodes[]; };
layout(std430, binding = kBindingTlasInstanceOrder) readonly buffer TlasOrder { uint tlasInstanceOrder[]; };

struct RayHit {
    float t;
    uint triangle; // global index (scene_buffers triangles[])
    uint instance;
    vec2 barycentric;
};

// Slab test; returns the entry distance, or kNoHitDistance on a miss.
float intersectBox(vec3 origin, vec3 invDir, vec3 lo, vec3 hi, float tMax) {
    vec3 t0 = (lo - origin) * invDir;
    vec3 t1 = (hi - origin) * invDir;
    vec3 tNear = min(t0, t1);
    vec3 tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    return enter <= leave ? enter : kNoHitDistance;
}

// Two-sided Moller-Trumbore; updates hit when closer than hit.t.
bool intersectTriangle(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2, inout float t,
                       out vec2 barycentric) {
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    vec3 p = cross(dir, e2);
    float det = dot(e1, p);
    if (det == 0.0) return false;
    float invDet = 1.0 / det;
    vec3 s = origin - p0;
    float u = dot(s, p) * invDet;
    if (u < 0.0 || u > 1.0) return false;
    vec3 q = cross(s, e1);
    float v = dot(dir, q) * invDet;
    if (v < 0.0 || u + v > 1.0) return false;
    float tHit = dot(e2, q) * invDet;
    if (tHit <= 0.0 || tHit >= t) return false;
    t = tHit;
    barycentric = vec2(u, v);
    return true;
}

vec3 safeInverse(vec3 d) {
    const float kTiny = 1e-30; // keeps 1/0 finite with the right sign for the slab test
    return 1.0 / vec3(abs(d.x) > kTiny ? d.x : (d.x >= 0.0 ? kTiny : -kTiny),
                      abs(d.y) > kTiny ? d.y : (d.y >= 0.0 ? kTiny : -kTiny),
                      abs(d.z) > kTiny ? d.z : (d.z >= 0.0 ? kTiny : -kTiny));
}

// Traversal goes down to the nearer child of an interior node whose box the ray enters and keeps
// the farther one on the stack with its entry distance. A kept node is dropped when popped if the
// hits found since lie before that distance (the box is not fetched or tested again). The stack
// holds node indices and entry distances (a stack per invocation: on a GPU a larger one costs
// occupancy). Expects stack, stackT, top, invDir, hit and current in scope, inside the level's
// loop over `current`; `nodes` is the level's array. ISPM_BVH_DESCEND goes on (continue) into the
// nearer child of interior node (a, b) the ray enters, if any; ISPM_BVH_POP goes on with the last
// kept node that still counts, or ends the loop (break).
#define ISPM_BVH_DESCEND(nodes, a, b, origin)                                                      \
    {                                                                                              \
        GpuBvhNode childA = nodes[a];                                                              \
        GpuBvhNode childB = nodes[b];                                                              \
        float tA = intersectBox(origin, invDir, childA.lo.xyz, childA.hi.xyz, hit.t);              \
        float tB = intersectBox(origin, invDir, childB.lo.xyz, childB.hi.xyz, hit.t);              \
        bool aFirst = tA <= tB;                                                                    \
        float tFar = aFirst ? tB : tA;                                                             \
        if (tFar < kNoHitDistance && top < kBvhStackSize) {                                        \
            stack[top] = aFirst ? b : a;                                                           \
            stackT[top] = tFar;                                                                    \
            ++top;                                                                                 \
        }                                                                                          \
        current = aFirst ? a : b;                                                                  \
        if (min(tA, tB) < kNoHitDistance) continue;                                                \
    }

#define ISPM_BVH_POP()                                                                             \
    {                                                                                              \
        bool popped = false;                                                                       \
        while (top > 0 && !popped) {                                                               \
            --top;                                                                                 \
            popped = stackT[top] < hit.t;                                                          \
            current = stack[top];                                                                  \
        }                                                                                          \
        if (!popped) break;                                                                        \
    }

// Closest hit in one instance (updates hit when closer than hit.t); with anyHit, the first hit
// found ends the search (a shadow ray asks only whether something is there).
bool intersectInstance(uint instanceIndex, vec3 originW, vec3 dirW, inout RayHit hit, bool anyHit) {
    GpuInstance inst = instances[instanceIndex];
    vec3 origin = (inst.objectFromWorld * vec4(originW, 1.0)).xyz;
    vec3 dir = mat3(inst.objectFromWorld) * dirW;
    vec3 invDir = safeInverse(dir);
    bool found = false;
    uint stack[kBvhStackSize];
    float stackT[kBvhStackSize];
    int top = 0;
    uint current = inst.range.z;
    // Read once per instance, so an opaque one pays a branch per hit and no material load.
    bool alphaTested = BVH_ALPHA_TEST != 0 && inst.range.w == kInstanceAlphaTested;
    GpuBvhNode root = blasNodes[current];
    if (intersectBox(origin, invDir, root.lo.xyz, root.hi.xyz, hit.t) >= kNoHitDistance) return false;
    while (true) {
        GpuBvhNode node = blasNodes[current];
        uint a = floatBitsToUint(node.lo.w);
        uint b = floatBitsToUint(node.hi.w);
        if ((b & kBvhLeafFlag) != 0u) {
            uint count = b & kBvhCountMask;
            for (uint i = a; i < a + count; ++i) {
                uint tri = blasTriangleOrder[i];
                uvec4 t = triangles[tri];
                vec2 bc;
                float tHit = hit.t;
                if (intersectTriangle(origin, dir, positions[t.x].xyz, positions[t.y].xyz,
                                      positions[t.z].xyz, tHit, bc)) {
                    // A cut-out point is no hit: the ray goes on through the leaf's gaps.
#if BVH_ALPHA_TEST
                    if (alphaTested && isHitCutOut(materials[t.w], tri, bc)) continue;
#endif
                    hit.t = tHit;
                    hit.triangle = tri;
                    hit.instance = instanceIndex;
                    hit.barycentric = bc;
                    if (anyHit) return true;
                    found = true;
                }
            }
        } else {
            ISPM_BVH_DESCEND(blasNodes, a, b, origin)
        }
        ISPM_BVH_POP()
    }
    return found;
}

// A hit along origin + t dir, t in (0, tMax): the closest, or with anyHit the first one found.
bool traceRayWith(vec3 origin, vec3 dir, float tMax, bool anyHit, out RayHit hit) {
    hit.t = tMax;
    hit.triangle = 0u;
    hit.instance = 0u;
    hit.barycentric = vec2(0.0);
    if (tlasNodes.length() == 0) return false;
    vec3 invDir = safeInverse(dir);
    bool found = false;
    uint stack[kBvhStackSize];
    float stackT[kBvhStackSize];
    int top = 0;
    uint current = 0u;
    GpuBvhNode root = tlasNodes[0];
    if (intersectBox(origin, invDir, root.lo.xyz, root.hi.xyz, hit.t) >= kNoHitDistance) return false;
    while (true) {
        GpuBvhNode node = tlasNodes[current];
        uint a = floatBitsToUint(node.lo.w);
        uint b = floatBitsToUint(node.hi.w);
        if ((b & kBvhLeafFlag) != 0u) {
            uint count = b & kBvhCountMask;
            for (uint i = a; i < a + count; ++i) {
                found = intersectInstance(tlasInstanceOrder[i], origin, dir, hit, anyHit) || found;
                if (anyHit && found) return true;
            }
        } else {
            ISPM_BVH_DESCEND(tlasNodes, a, b, origin)
        }
        ISPM_BVH_POP()
    }
    return found;
}

// Closest hit along origin + t dir, t in (0, tMax).
bool traceRay(vec3 origin, vec3 dir, float tMax, out RayHit hit) {
    return traceRayWith(origin, dir, tMax, false, hit);
}

// Whether anything lies on origin + t dir, t in (0, tMax): stops at the first hit found.
bool isRayBlocked(vec3 origin, vec3 dir, float tMax) {
    RayHit hit;
    return traceRayWith(origin, dir, tMax, true, hit);
}

// World-space unit geometric normal of a hit (the triangle's winding decides its side).
vec3 computeHitNormal(RayHit hit) {
    uvec4 t = triangles[hit.triangle];
    vec3 p0 = positions[t.x].xyz;
    vec3 n = cross(positions[t.y].xyz - p0, positions[t.z].xyz - p0);
    return normalize(transpose(mat3(instances[hit.instance].objectFromWorld)) * n);
}

// The hit's shading normal on the side of `geometric` (computeHitNormal turned to either side),
// normal maps applied; needs lib/vertex_attributes.glsl included before, and
// lib/scene_textures.glsl unless SCENE_NORMAL_MAPS is 0 (a scene without normal maps,
// GpuScene::getRayDefines: then no material is read here).
#ifndef SCENE_NORMAL_MAPS
#define SCENE_NORMAL_MAPS 1
#endif
#ifdef ISPM_VERTEX_ATTRIBUTES_GLSL
#if SCENE_NORMAL_MAPS && !defined(ISPM_SCENE_TEXTURES_GLSL)
#error "computeHitShadingNormal reads normal maps: include lib/scene_textures.glsl before bvh.glsl"
#endif
vec3 computeHitShadingNormal(RayHit hit, vec3 geometric) {
#if SCENE_NORMAL_MAPS
    GpuMaterial m = materials[triangles[hit.triangle].w];
    if (hasNormalMap(m)) {
        return computeMappedShadingNormal(m, hit.triangle, hit.instance, hit.barycentric,
                                          geometric);
    }
#endif
    return computeShadingNormal(hit.triangle, hit.instance, hit.barycentric, geometric);
}
#endif

bool overlapsBox(vec3 aLo, vec3 aHi, vec3 bLo, vec3 bHi) {
    return all(lessThanEqual(aLo, bHi)) && all(lessThanEqual(bLo, aHi));
}

// Box queries (define ISPM_BVH_BOX_VISITOR before including, and define the visitor after):
// visitBoxTriangle gets, in world space, every triangle whose bounds and plane both overlap the
// world box (conservative: a triangle's bounds and plane, not the triangle).
#ifdef ISPM_BVH_BOX_VISITOR
void visitBoxTriangle(vec3 p0, vec3 p1, vec3 p2);

void queryInstanceBox(uint instanceIndex, vec3 loW, vec3 hiW) {
    GpuInstance inst = instances[instanceIndex];
    // The world box in object space, boxed again (Arvo: the half extent through |M|).
    vec3 centre = (inst.objectFromWorld * vec4(0.5 * (loW + hiW), 1.0)).xyz;
    mat3 m = mat3(inst.objectFromWorld);
    vec3 half_ = (mat3(abs(m[0]), abs(m[1]), abs(m[2]))) * (0.5 * (hiW - loW));
    vec3 lo = centre - half_;
    vec3 hi = centre + half_;
    uint stack[kBvhStackSize];
    int top = 0;
    stack[top++] = inst.range.z;
    while (top > 0) {
        GpuBvhNode node = blasNodes[stack[--top]];
        if (!overlapsBox(lo, hi, node.lo.xyz, node.hi.xyz)) continue;
        uint a = floatBitsToUint(node.lo.w);
        uint b = floatBitsToUint(node.hi.w);
        if ((b & kBvhLeafFlag) != 0u) {
            uint count = b & kBvhCountMask;
            for (uint i = a; i < a + count; ++i) {
                uvec4 t = triangles[blasTriangleOrder[i]];
                vec3 p0 = positions[t.x].xyz;
                vec3 p1 = positions[t.y].xyz;
                vec3 p2 = positions[t.z].xyz;
                if (!overlapsBox(lo, hi, min(p0, min(p1, p2)), max(p0, max(p1, p2)))) continue;
                // The triangle's plane must cross the box too (a slanted triangle's bounds
                // reach far from it).
                vec3 normal = cross(p1 - p0, p2 - p0);
                if (abs(dot(normal, centre - p0)) > dot(abs(normal), half_)) continue;
                visitBoxTriangle((inst.worldFromObject * vec4(p0, 1.0)).xyz,
                                 (inst.worldFromObject * vec4(p1, 1.0)).xyz,
                                 (inst.worldFromObject * vec4(p2, 1.0)).xyz);
            }
        } else if (top + 2 <= kBvhStackSize) {
            stack[top++] = a;
            stack[top++] = b;
        }
    }
}

void queryBox(vec3 loW, vec3 hiW) {
    if (tlasNodes.length() == 0) return;
    uint stack[kBvhStackSize];
    int top = 0;
    stack[top++] = 0u;
    while (top > 0) {
        GpuBvhNode node = tlasNodes[stack[--top]];
        if (!overlapsBox(loW, hiW, node.lo.xyz, node.hi.xyz)) continue;
        uint a = floatBitsToUint(node.lo.w);
        uint b = floatBitsToUint(node.hi.w);
        if ((b & kBvhLeafFlag) != 0u) {
            uint count = b & kBvhCountMask;
            for (uint i = a; i < a + count; ++i) queryInstanceBox(tlasInstanceOrder[i], loW, hiW);
        } else if (top + 2 <= kBvhStackSize) {
            stack[top++] = a;
            stack[top++] = b;
        }
    }
}
#endif
