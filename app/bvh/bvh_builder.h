// Binned SAH builder over primitive boxes, shared by both levels: triangles of one mesh (bottom
// level, built once at load) and instances (top level, rebuilt every frame).
#pragma once

#include "bvh/bvh_node.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ispm {

struct BvhBuildParams {
    uint32_t maxLeafSize = 4; // a node with at most this many primitives becomes a leaf
    uint32_t binCount = 16;   // SAH candidates on the longest centroid axis
    float traversalCost = 1.0f;
    float intersectionCost = 1.0f;
};

// Nodes with child indices relative to nodes[0] (the root) and leaf ranges into order; order
// lists each primitive index in [0, primitive count) exactly once.
struct BvhTree {
    std::vector<gpu::GpuBvhNode> nodes;
    std::vector<uint32_t> order;
    uint32_t depth = 0; // levels below the root: the traversal stack holds at most this many
};

// No primitives give a single empty leaf, so the root always exists.
BvhTree buildBvh(std::span<const Aabb> primitiveBounds, const BvhBuildParams& params = {});

float computeSurfaceArea(const Aabb& box);

} // namespace ispm
