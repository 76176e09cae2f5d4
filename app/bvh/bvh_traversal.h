// Ray queries on the CPU over exactly the arrays the GPU traverses (BvhScene), plus a brute-force
// reference for tests. The loop structure mirrors a stack-based GLSL traversal.
#pragma once

#include "bvh/bvh_scene.h"
#include "scene/scene.h"

#include <cstdint>
#include <limits>
#include <optional>

namespace ispm {

// World space; direction must be unit length, so t is a distance in metres. Hits count for t in
// (0, tMax).
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    float tMax = std::numeric_limits<float>::infinity();
};

struct Hit {
    uint32_t instanceIndex = 0;
    uint32_t triangleIndex = 0;   // global, as GpuScene numbers triangles
    float t = 0.0f;               // world-space distance along the ray
    glm::vec2 barycentrics{0.0f}; // weights of the triangle's second and third vertex
};

// The closest hit; equal distances go to the lowest (instance, triangle), so the result does not
// depend on the order of the search.
std::optional<Hit> intersect(const BvhScene& bvh, const Scene& scene, const Ray& ray);

// Whether anything lies within (0, tMax): shadow and visibility rays.
bool intersectAny(const BvhScene& bvh, const Scene& scene, const Ray& ray);

// Every triangle of every instance, with the same triangle test: the reference for tests.
std::optional<Hit> intersectBruteForce(const Scene& scene, const Ray& ray);

} // namespace ispm
