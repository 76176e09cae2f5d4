// Light cameras: every light is a camera. Spotlights get one perspective view (the cone's full
// angle), point lights six 90-degree faces, the sun one orthographic view fitted to the scene.
// Pure math (no GL), so it is unit-tested on its own.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace ispm {

struct LightCamera {
    uint32_t lightIndex = 0;
    glm::mat4 viewFromWorld{1.0f};
    glm::mat4 clipFromView{1.0f};
    glm::vec3 origin{0.0f}; // eye, or the centre of the near plane for the sun
    glm::vec3 axis{0.0f};   // unit view direction
    bool isOrthographic = false;
    float texelPerDepth = 0.0f; // perspective: texel size (m) per metre of depth
    float texelSizeM = 0.0f;    // orthographic: texel size in metres
    glm::mat4 getClipFromWorld() const { return clipFromView * viewFromWorld; }
};

// All light cameras of the scene in light order; `resolution` is the light G-buffer size.
std::vector<LightCamera> computeLightCameras(const Scene& scene, int resolution);

// Near/far planes that enclose `bounds` as seen from `eye` along `axis`.
void computeDepthRange(const Aabb& bounds, const glm::vec3& eye, const glm::vec3& axis,
                       float& nearM, float& farM);

} // namespace ispm
