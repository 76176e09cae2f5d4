// The scene model's computations: bounds, triangle counts, spot falloff and camera matrices.
#include "scene/scene.h"

#include <shared/scene_data.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace ispm {

const char* getLightTypeName(LightType type) {
    switch (type) {
    case LightType::Point:
        return "point";
    case LightType::Spot:
        return "spot";
    case LightType::Sun:
        return "sun";
    }
    return "light";
}

float computeSpotFalloff(float cosAngle, float innerDeg, float outerDeg) {
    // The shaders' own function (shared/scene_data.h), so CPU and GPU agree to the bit.
    return gpu::computeSpotFalloffCos(cosAngle, std::cos(glm::radians(innerDeg)),
                                      std::cos(glm::radians(outerDeg)));
}

Aabb Mesh::computeBounds() const {
    Aabb bounds;
    for (const glm::vec3& p : positions)
        bounds.extend(p);
    return bounds;
}

Aabb transformBounds(const Aabb& box, const glm::mat4& m) {
    Aabb out;
    if (box.isEmpty()) return out;
    for (int corner = 0; corner < kAabbCornerCount; ++corner) {
        out.extend(glm::vec3(m * glm::vec4(box.getCorner(corner), 1.0f)));
    }
    return out;
}

Aabb computeUnion(std::span<const Aabb> boxes) {
    Aabb bounds;
    for (const Aabb& box : boxes)
        bounds.extend(box);
    return bounds;
}

Aabb Scene::computeWorldBounds() const {
    return computeUnion(computeInstanceBounds());
}

std::vector<Aabb> Scene::computeInstanceBounds() const {
    // Each mesh's box, transformed: cheap enough to call every frame.
    std::vector<Aabb> boxes;
    boxes.reserve(instances.size());
    for (const Instance& instance : instances) {
        const Aabb world = transformBounds(meshes.at(instance.meshIndex).computeBounds(),
                                           instance.worldFromObject);
        if (!world.isEmpty()) boxes.push_back(world);
    }
    return boxes;
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

glm::mat4 computeClipShift(glm::vec2 shiftPx, glm::vec2 sizePx) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(2.0f * shiftPx / sizePx, 0.0f));
}

bool isSameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.target == b.target && a.up == b.up &&
           a.fovYDeg == b.fovYDeg && a.nearM == b.nearM && a.farM == b.farM;
}

} // namespace ispm
