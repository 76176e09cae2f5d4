// The scene's two-level BVH in the GPU layout of shaders/shared/bvh_data.h: one bottom level per
// mesh in object space (built once at load, all concatenated), one top level over the instances in
// world space (rebuilt or refitted every frame as instances move).
#pragma once

#include "bvh/bvh_builder.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace ispm {

struct BvhScene {
    // Bottom level: every mesh's nodes in one array (kBindingBlasNodes) with absolute child
    // indices, leaf ranges into blasTriangleOrder (kBindingBlasTriangleOrder), which holds global
    // triangle indices (mesh's first triangle + local index, as GpuScene flattens them).
    std::vector<gpu::GpuBvhNode> blasNodes;
    std::vector<uint32_t> blasTriangleOrder;
    std::vector<uint32_t> meshBlasRoots;      // per mesh: its root in blasNodes
    std::vector<uint32_t> meshFirstTriangles; // per mesh: global index of its first triangle
    // Top level (kBindingTlasNodes, root at 0): leaves hold instances through tlasInstanceOrder
    // (kBindingTlasInstanceOrder). Instances of meshes without triangles are left out.
    std::vector<gpu::GpuBvhNode> tlasNodes;
    std::vector<uint32_t> tlasInstanceOrder;
    std::vector<glm::mat4> objectFromWorld; // per instance, inverse of worldFromObject
    uint32_t blasDepth = 0;                 // deepest bottom level, levels below its root
    uint32_t tlasDepth = 0;
};

// Instances are one primitive each; leaves of one keep the GPU's two-level loop simple.
inline constexpr BvhBuildParams kTlasBuildParams{.maxLeafSize = 1};

// Both levels. meshParams shape the bottom levels.
BvhScene buildSceneBvh(const Scene& scene, const BvhBuildParams& meshParams = {});

// A new top level for the instances' current transforms (instances may have been added/removed;
// meshes must be the ones the bottom levels were built from).
void rebuildTopLevel(BvhScene& bvh, const Scene& scene);

// New boxes for the top level's existing tree: cheaper than a rebuild, but the tree degrades as
// instances move far. The instance list must be the one the top level was built for.
void refitTopLevel(BvhScene& bvh, const Scene& scene);

// World-space box of one instance: its bottom-level root box's 8 corners, transformed.
Aabb computeInstanceBounds(const BvhScene& bvh, const Scene& scene, uint32_t instanceIndex);

} // namespace ispm
