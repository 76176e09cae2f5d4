// Light cameras: every light is a camera. Spotlights get one perspective view (the cone's full
// angle), point lights six 90-degree faces, the sun one orthographic view fitted to the scene.
// Pure math (no GL), so it is unit-tested on its own.
#pragma once

#include "bvh/bvh_scene.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <optional>
#include <span>
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
    // A shadow-only view (fitSunView): drawn into the light G-buffer and read by the shadow test,
    // never a source of photons.
    bool isShadowOnly = false;
    glm::mat4 getClipFromWorld() const { return clipFromView * viewFromWorld; }
};

// All light cameras of the scene in light order; `resolution` is the light G-buffer size.
std::vector<LightCamera> computeLightCameras(const Scene& scene, int resolution);

// Surface points the viewer sees: the first hits of a raysPerSide x raysPerSide grid of camera
// rays through the image (aspect = width / height), traced on the CPU.
std::vector<glm::vec3> sampleVisiblePoints(const BvhScene& bvh, const Scene& scene,
                                           const Camera& camera, float aspect, int raysPerSide);

// The sun's second, finer camera (the thesis's sun cascades, §7.2): the scene-wide `sun` view
// narrowed to a square around `visible` (the points the viewer sees, sampleVisiblePoints) in
// the sun's image plane, with a margin for what lies between the samples; same direction and
// depth range, so every occluder between the sun and those points is in it. None when the
// square would not be finer than the sun's own by kMinSunRefinement, or nothing is visible.
std::optional<LightCamera> fitSunView(const LightCamera& sun, const std::vector<glm::vec3>& visible,
                                      int resolution);

// A box holding every point of `sceneBounds` the light reaches directly: a spot light's cone
// (outer half-angle under kMaxBoundedSpotDeg) up to where the scene ends along its axis, cut to
// the scene. Empty when the cone meets none of it. None for lights that reach every direction
// (point lights, the sun, wider spots). The direct pass shades such a light only where the box
// projects (DirectPass).
std::optional<Aabb> computeLitBounds(const Light& light, const Aabb& sceneBounds);
inline constexpr float kMaxBoundedSpotDeg = 85.0f; // wider: the cone's box is the scene's

// Near/far planes that enclose `bounds` as seen from `eye` along `axis`. The near plane is
// kNearFraction of the far one, or nearer where one of `parts` (the instances' boxes) is: half
// the distance to a part the eye is outside of, that fraction of a part's own depth when the eye
// is inside it. A small room beside a huge distant object keeps a near plane fit for the room
// (1e-4 of a far plane 7e6 m away would clip the whole room).
void computeDepthRange(const Aabb& bounds, std::span<const Aabb> parts, const glm::vec3& eye,
                       const glm::vec3& axis, float& nearM, float& farM);

} // namespace ispm
