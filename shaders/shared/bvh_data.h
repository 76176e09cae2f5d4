// The two-level BVH as the GPU sees it (std430 storage buffers): node layout and binding points.
// Included by C++ (app/bvh builds the arrays, app/render uploads them) and by GLSL (traversal).
#ifndef ISPM_BVH_DATA_H
#define ISPM_BVH_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// One node of either level. xyz of lo/hi is the box (object space for the bottom level, world
// space for the top level). The w components are not floats: they hold uint bits, written with
// std::bit_cast in C++ and read with floatBitsToUint in GLSL (only moved, never used in arithmetic,
// so denormal or NaN patterns survive).
//   interior: lo.w = left child index,              hi.w = right child index
//   leaf:     lo.w = first index into the order array, hi.w = primitive count | kBvhLeafFlag
// Child indices are absolute in the node array they live in (all meshes' bottom levels share one
// array), children always come after their parent, and the top level's root is node 0.
// Leaf ranges index the order arrays: kBindingBlasTriangleOrder holds global triangle indices (the
// same numbering as kBindingTriangles), kBindingTlasInstanceOrder holds instance indices.
// An instance's bottom-level root node index travels in GpuInstance::range.z.
struct GpuBvhNode {
    vec4 lo;
    vec4 hi;
};
ISPM_STATIC_ASSERT_SIZE(GpuBvhNode, 32);

ISPM_CONST uint kBvhLeafFlag = 0x80000000u;  // set in hi.w of a leaf
ISPM_CONST uint kBvhCountMask = 0x7fffffffu; // hi.w & mask = a leaf's primitive count
// Traversal stack entries per level; the builders keep every tree's depth below it.
ISPM_CONST int kBvhStackSize = 64;

// Binding points (storage buffers), continuing scene_data.h's numbering.
// A ray's "no limit" and the entry distance of a missed box (bvh.glsl): past every scene.
ISPM_CONST float kNoHitDistance = 3.0e38f;

ISPM_CONST int kBindingBlasNodes = 7;          // GpuBvhNode, every mesh's bottom level
ISPM_CONST int kBindingBlasTriangleOrder = 8;  // uint, global triangle index per leaf slot
ISPM_CONST int kBindingTlasNodes = 9;          // GpuBvhNode, root at 0
ISPM_CONST int kBindingTlasInstanceOrder = 10; // uint, instance index per leaf slot

ISPM_NAMESPACE_END

#endif
