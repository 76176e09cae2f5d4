// Light camera construction: frusta enclose the scene bounds so that every surface a light can
// reach lands in its G-buffer (and shadow map).
#include "render/light_cameras.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace ispm {
namespace {

constexpr float kNearFraction = 1e-4f; // near plane as a fraction of far: depth is 32-bit float
constexpr float kMinNearM = 1e-4f;     // never put the near plane on the eye
constexpr float kBoundsMargin = 1.01f; // grow fitted volumes so border texels are inside
constexpr float kPointFaceFovDeg = 90.0f;

glm::vec3 pickUp(const glm::vec3& axis) {
    // Any vector not parallel to the axis; +y unless the axis is (nearly) vertical.
    constexpr float kNearlyVertical = 0.99f;
    return std::abs(axis.y) > kNearlyVertical ? glm::vec3(0.0f, 0.0f, 1.0f)
                                              : glm::vec3(0.0f, 1.0f, 0.0f);
}

std::array<glm::vec3, kAabbCornerCount> getCorners(const Aabb& b) {
    std::array<glm::vec3, kAabbCornerCount> corners;
    for (int i = 0; i < kAabbCornerCount; ++i)
        corners[static_cast<size_t>(i)] = b.getCorner(i);
    return corners;
}

LightCamera makePerspective(uint32_t lightIndex, const glm::vec3& eye, const glm::vec3& axis,
                            const glm::vec3& up, float fovYDeg, const Aabb& bounds,
                            int resolution) {
    LightCamera cam;
    cam.lightIndex = lightIndex;
    cam.origin = eye;
    cam.axis = glm::normalize(axis);
    cam.viewFromWorld = glm::lookAt(eye, eye + cam.axis, up);
    float nearM = 0.0f;
    float farM = 0.0f;
    computeDepthRange(bounds, eye, cam.axis, nearM, farM);
    cam.clipFromView = glm::perspective(glm::radians(fovYDeg), 1.0f, nearM, farM);
    cam.texelPerDepth =
        2.0f * std::tan(glm::radians(fovYDeg) * 0.5f) / static_cast<float>(resolution);
    return cam;
}

} // namespace

void computeDepthRange(const Aabb& bounds, const glm::vec3& eye, const glm::vec3& axis,
                       float& nearM, float& farM) {
    float maxDepth = 0.0f;
    for (const glm::vec3& c : getCorners(bounds))
        maxDepth = std::max(maxDepth, glm::dot(c - eye, axis));
    farM = std::max(maxDepth * kBoundsMargin, 2.0f * kMinNearM);
    // The near plane must not clip anything in front of the eye: keep it small.
    nearM = std::max(kMinNearM, farM * kNearFraction);
}

std::vector<LightCamera> computeLightCameras(const Scene& scene, int resolution) {
    const Aabb bounds = scene.computeWorldBounds();
    std::vector<LightCamera> cameras;
    for (uint32_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        switch (light.type) {
        case LightType::Spot: {
            const glm::vec3 axis = glm::normalize(light.direction);
            cameras.push_back(makePerspective(i, light.position, axis, pickUp(axis),
                                              2.0f * light.outerDeg, bounds, resolution));
            break;
        }
        case LightType::Point: {
            // Cube faces in the usual +x, -x, +y, -y, +z, -z order.
            const glm::vec3 axes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
            for (const glm::vec3& axis : axes) {
                cameras.push_back(makePerspective(i, light.position, axis, pickUp(axis),
                                                  kPointFaceFovDeg, bounds, resolution));
            }
            break;
        }
        case LightType::Sun: {
            LightCamera cam;
            cam.lightIndex = i;
            cam.isOrthographic = true;
            cam.axis = glm::normalize(light.direction);
            const glm::vec3 centre = bounds.getCenter();
            const float radius = 0.5f * glm::length(bounds.getExtent()) * kBoundsMargin;
            const glm::vec3 eye = centre - cam.axis * radius;
            cam.viewFromWorld = glm::lookAt(eye, centre, pickUp(cam.axis));
            // Fit the square footprint to the bounds' projection on the view plane.
            float halfSize = 0.0f;
            for (const glm::vec3& c : getCorners(bounds)) {
                const glm::vec4 v = cam.viewFromWorld * glm::vec4(c, 1.0f);
                halfSize = std::max({halfSize, std::abs(v.x), std::abs(v.y)});
            }
            halfSize = std::max(halfSize * kBoundsMargin, kMinNearM);
            cam.clipFromView =
                glm::ortho(-halfSize, halfSize, -halfSize, halfSize, 0.0f, 2.0f * radius);
            cam.origin = eye;
            cam.texelSizeM = 2.0f * halfSize / static_cast<float>(resolution);
            cameras.push_back(cam);
            break;
        }
        }
    }
    return cameras;
}

} // namespace ispm
