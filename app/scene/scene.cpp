// The scene model's computations: bounds, triangle counts, spot falloff and camera matrices.
#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace ispm {

float computeSpotFalloff(float cosAngle, float innerDeg, float outerDeg) {
    const float cosInner = std::cos(glm::radians(innerDeg));
    const float cosOuter = std::cos(glm::radians(outerDeg));
    if (cosInner <= cosOuter) {
        // inner == outer: a hard edge, lit up to and including the cone's boundary.
        return cosAngle >= cosOuter ? 1.0f : 0.0f;
    }
    const float s = std::clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    return s * s * (3.0f - 2.0f * s);
}

Aabb Mesh::computeBounds() const {
    Aabb bounds;
    for (const glm::vec3& p : positions)
        bounds.extend(p);
    return bounds;
}

Aabb Scene::computeWorldBounds() const {
    // Transforms each mesh's box corners: exact for translations and scales, conservative when
    // an instance rotates, and cheap enough to call every frame.
    constexpr int kCornerCount = 8;
    Aabb bounds;
    for (const Instance& instance : instances) {
        const Aabb local = meshes.at(instance.meshIndex).computeBounds();
        if (local.isEmpty()) continue;
        for (int corner = 0; corner < kCornerCount; ++corner) {
            const glm::vec3 p{(corner & 1) ? local.hi.x : local.lo.x,
                              (corner & 2) ? local.hi.y : local.lo.y,
                              (corner & 4) ? local.hi.z : local.lo.z};
            bounds.extend(glm::vec3(instance.worldFromObject * glm::vec4(p, 1.0f)));
        }
    }
    return bounds;
}

size_t Scene::countTriangles() const {
    // What is drawn: a mesh placed twice counts twice.
    size_t count = 0;
    for (const Instance& instance : instances) {
        count += meshes.at(instance.meshIndex).triangles.size();
    }
    return count;
}

glm::mat4 computeViewFromWorld(const Camera& camera) {
    return glm::lookAt(camera.position, camera.target, camera.up);
}

glm::mat4 computeClipFromView(const Camera& camera, float aspect, float nearM, float farM) {
    return glm::perspective(glm::radians(camera.fovYDeg), aspect, nearM, farM);
}

} // namespace ispm
