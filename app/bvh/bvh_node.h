// Reading and writing the GPU node encoding of shaders/shared/bvh_data.h from C++: the w
// components carry uint bits, so every access goes through std::bit_cast.
#pragma once

#include "scene/scene.h"
#include <shared/bvh_data.h>

#include <bit>
#include <cstdint>

namespace ispm {

inline gpu::GpuBvhNode makeInteriorNode(const Aabb& box, uint32_t left, uint32_t right) {
    return {glm::vec4(box.lo, std::bit_cast<float>(left)),
            glm::vec4(box.hi, std::bit_cast<float>(right))};
}

inline gpu::GpuBvhNode makeLeafNode(const Aabb& box, uint32_t first, uint32_t count) {
    return {glm::vec4(box.lo, std::bit_cast<float>(first)),
            glm::vec4(box.hi, std::bit_cast<float>(count | gpu::kBvhLeafFlag))};
}

inline bool isLeaf(const gpu::GpuBvhNode& node) {
    return (std::bit_cast<uint32_t>(node.hi.w) & gpu::kBvhLeafFlag) != 0;
}
// Interior nodes.
inline uint32_t getLeftChild(const gpu::GpuBvhNode& node) {
    return std::bit_cast<uint32_t>(node.lo.w);
}
inline uint32_t getRightChild(const gpu::GpuBvhNode& node) {
    return std::bit_cast<uint32_t>(node.hi.w);
}
// Leaves.
inline uint32_t getFirstPrimitive(const gpu::GpuBvhNode& node) {
    return std::bit_cast<uint32_t>(node.lo.w);
}
inline uint32_t getPrimitiveCount(const gpu::GpuBvhNode& node) {
    return std::bit_cast<uint32_t>(node.hi.w) & gpu::kBvhCountMask;
}

inline Aabb getNodeBounds(const gpu::GpuBvhNode& node) {
    Aabb box;
    box.lo = glm::vec3(node.lo);
    box.hi = glm::vec3(node.hi);
    return box;
}

// Replaces the box and keeps the w bits (used by refitting).
inline void setNodeBounds(gpu::GpuBvhNode& node, const Aabb& box) {
    node.lo = glm::vec4(box.lo, node.lo.w);
    node.hi = glm::vec4(box.hi, node.hi.w);
}

} // namespace ispm
