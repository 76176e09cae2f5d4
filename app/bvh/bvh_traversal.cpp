// Two-level stack traversal: the top level finds instances, the ray moves into each instance's
// object space (unnormalised, so t stays the world-space distance), the bottom level finds
// triangles, Möller-Trumbore tests them from both sides.
#include "bvh/bvh_traversal.h"

#include <array>
#include <cassert>
#include <utility>

namespace ispm {
namespace {

// Widens each slab's far distance so rounding cannot cull a box the ray grazes, flat boxes of
// axis-aligned triangles included (pbrt's 1 + 2 gamma(3), with a factor of 2 to spare).
constexpr float kBoxFarSlack = 1.0f + 2.0f * 3.0f * 0.5f * std::numeric_limits<float>::epsilon();

struct ObjectRay {
    glm::vec3 origin;
    glm::vec3 direction; // world direction mapped by objectFromWorld: not unit under scaling
    glm::vec3 invDirection;
};

ObjectRay transformRay(const glm::mat4& objectFromWorld, const Ray& ray) {
    ObjectRay r;
    r.origin = glm::vec3(objectFromWorld * glm::vec4(ray.origin, 1.0f));
    r.direction = glm::mat3(objectFromWorld) * ray.direction;
    r.invDirection = 1.0f / r.direction; // +-inf for zero components, handled by the slab test
    return r;
}

// Slab test; comparisons are written so a NaN (0 x inf on a slab plane) leaves the interval alone.
bool intersectBox(const gpu::GpuBvhNode& node, const glm::vec3& origin,
                  const glm::vec3& invDirection, float tMax, float& tEntry) {
    float t0 = 0.0f;
    float t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        float tNear = (node.lo[a] - origin[a]) * invDirection[a];
        float tFar = (node.hi[a] - origin[a]) * invDirection[a];
        if (tNear > tFar) std::swap(tNear, tFar);
        tFar *= kBoxFarSlack;
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
        if (t0 > t1) return false;
    }
    tEntry = t0;
    return true;
}

// Möller-Trumbore without culling; t is in units of the ray's direction.
bool intersectTriangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                       const ObjectRay& ray, float& t, glm::vec2& barycentrics) {
    const glm::vec3 e1 = p1 - p0;
    const glm::vec3 e2 = p2 - p0;
    const glm::vec3 pv = glm::cross(ray.direction, e2);
    const float det = glm::dot(e1, pv);
    if (det == 0.0f) return false; // the ray lies in the triangle's plane
    const float invDet = 1.0f / det;
    const glm::vec3 tv = ray.origin - p0;
    const float u = glm::dot(tv, pv) * invDet;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 qv = glm::cross(tv, e1);
    const float v = glm::dot(ray.direction, qv) * invDet;
    if (v < 0.0f || u + v > 1.0f) return false;
    t = glm::dot(e2, qv) * invDet;
    barycentrics = {u, v};
    return t > 0.0f;
}

// The best hit so far; ties in t go to the lowest (instance, triangle).
struct HitRecord {
    Hit hit;
    bool found = false;
    float tMax = 0.0f;

    bool consider(uint32_t instance, uint32_t triangle, float t, const glm::vec2& bary) {
        if (t >= tMax && !(found && t == tMax)) return false;
        if (found && t == tMax &&
            std::pair(instance, triangle) >= std::pair(hit.instanceIndex, hit.triangleIndex)) {
            return false;
        }
        hit = {instance, triangle, t, bary};
        found = true;
        tMax = t;
        return true;
    }
};

// Tests one triangle of one instance; returns true when an any-hit query may stop.
bool testTriangle(const Scene& scene, uint32_t meshIndex, uint32_t firstTriangle, uint32_t instance,
                  uint32_t globalTriangle, const ObjectRay& ray, HitRecord& record, bool isAnyHit) {
    const Mesh& mesh = scene.meshes[meshIndex];
    const glm::uvec3 tri = mesh.triangles[globalTriangle - firstTriangle];
    float t = 0.0f;
    glm::vec2 bary{0.0f};
    if (!intersectTriangle(mesh.positions[tri.x], mesh.positions[tri.y], mesh.positions[tri.z], ray,
                           t, bary)) {
        return false;
    }
    return record.consider(instance, globalTriangle, t, bary) && isAnyHit;
}

// Visits the leaves of one tree whose boxes the ray enters before record.tMax, nearest child
// first; visitLeaf returns true to stop.
template <typename VisitLeaf>
bool traverseTree(const std::vector<gpu::GpuBvhNode>& nodes, uint32_t root, const glm::vec3& origin,
                  const glm::vec3& invDirection, const HitRecord& record, VisitLeaf&& visitLeaf) {
    std::array<uint32_t, gpu::kBvhStackSize> stack{};
    std::array<float, gpu::kBvhStackSize> stackEntry{};
    size_t top = 0;
    float tEntry = 0.0f;
    if (!intersectBox(nodes[root], origin, invDirection, record.tMax, tEntry)) return false;
    uint32_t current = root;
    while (true) {
        const gpu::GpuBvhNode& node = nodes[current];
        bool descended = false;
        if (isLeaf(node)) {
            if (visitLeaf(node)) return true;
        } else {
            uint32_t near = getLeftChild(node);
            uint32_t far = getRightChild(node);
            float tNear = 0.0f;
            float tFar = 0.0f;
            bool hitNear = intersectBox(nodes[near], origin, invDirection, record.tMax, tNear);
            bool hitFar = intersectBox(nodes[far], origin, invDirection, record.tMax, tFar);
            if (hitNear && hitFar && tFar < tNear) {
                std::swap(near, far);
                std::swap(tNear, tFar);
            } else if (!hitNear && hitFar) {
                std::swap(near, far);
                std::swap(tNear, tFar);
                std::swap(hitNear, hitFar);
            }
            if (hitFar) {
                assert(top < stack.size());
                stack[top] = far;
                stackEntry[top++] = tFar;
            }
            if (hitNear) {
                current = near;
                descended = true;
            }
        }
        while (!descended) {
            if (top == 0) return false;
            --top;
            // The best hit may have moved closer since this node was pushed.
            if (stackEntry[top] > record.tMax) continue;
            current = stack[top];
            descended = true;
        }
    }
}

std::optional<Hit> traverseScene(const BvhScene& bvh, const Scene& scene, const Ray& ray,
                                 bool isAnyHit) {
    HitRecord record;
    record.tMax = ray.tMax;
    const glm::vec3 invDirection = 1.0f / ray.direction;
    traverseTree(
        bvh.tlasNodes, 0, ray.origin, invDirection, record, [&](const gpu::GpuBvhNode& tlasLeaf) {
            for (uint32_t k = 0; k < getPrimitiveCount(tlasLeaf); ++k) {
                const uint32_t instance = bvh.tlasInstanceOrder[getFirstPrimitive(tlasLeaf) + k];
                const uint32_t meshIndex = scene.instances[instance].meshIndex;
                const uint32_t firstTriangle = bvh.meshFirstTriangles[meshIndex];
                const ObjectRay objectRay = transformRay(bvh.objectFromWorld[instance], ray);
                const bool stop = traverseTree(
                    bvh.blasNodes, bvh.meshBlasRoots[meshIndex], objectRay.origin,
                    objectRay.invDirection, record, [&](const gpu::GpuBvhNode& blasLeaf) {
                        const uint32_t first = getFirstPrimitive(blasLeaf);
                        for (uint32_t j = 0; j < getPrimitiveCount(blasLeaf); ++j) {
                            if (testTriangle(scene, meshIndex, firstTriangle, instance,
                                             bvh.blasTriangleOrder[first + j], objectRay, record,
                                             isAnyHit)) {
                                return true;
                            }
                        }
                        return false;
                    });
                if (stop) return true;
            }
            return false;
        });
    if (!record.found) return std::nullopt;
    return record.hit;
}

} // namespace

std::optional<Hit> intersect(const BvhScene& bvh, const Scene& scene, const Ray& ray) {
    return traverseScene(bvh, scene, ray, false);
}

bool intersectAny(const BvhScene& bvh, const Scene& scene, const Ray& ray) {
    return traverseScene(bvh, scene, ray, true).has_value();
}

std::optional<Hit> intersectBruteForce(const Scene& scene, const Ray& ray) {
    HitRecord record;
    record.tMax = ray.tMax;
    std::vector<uint32_t> meshFirstTriangles;
    uint32_t firstTriangle = 0;
    for (const Mesh& mesh : scene.meshes) {
        meshFirstTriangles.push_back(firstTriangle);
        firstTriangle += static_cast<uint32_t>(mesh.triangles.size());
    }
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const uint32_t meshIndex = scene.instances[i].meshIndex;
        // The same inverse as BvhScene's, so both see bit-identical object-space rays.
        const ObjectRay objectRay =
            transformRay(glm::inverse(scene.instances[i].worldFromObject), ray);
        const uint32_t first = meshFirstTriangles[meshIndex];
        const auto count = static_cast<uint32_t>(scene.meshes[meshIndex].triangles.size());
        for (uint32_t j = 0; j < count; ++j) {
            testTriangle(scene, meshIndex, first, i, first + j, objectRay, record, false);
        }
    }
    if (!record.found) return std::nullopt;
    return record.hit;
}

} // namespace ispm
