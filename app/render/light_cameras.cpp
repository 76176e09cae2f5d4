// Light camera construction: frusta enclose the scene bounds so that every surface a light can
// reach lands in its G-buffer (and shadow map).
#include "render/light_cameras.h"

#include "bvh/bvh_traversal.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ispm {
namespace {

constexpr float kNearFraction = 1e-4f; // near plane as a fraction of far: depth is 32-bit float
// Far planes are at least this fraction of the bounds' diagonal (an eye beyond the scene, looking
// away from it), so the near plane follows the scene's size: a scene a micrometre across keeps
// its depth range (a floor in metres would clip it away) and never lies on the eye.
constexpr float kMinFarFraction = 1e-3f;
constexpr float kMinFootprintM = 1e-30f; // a sun's footprint even over a scene of one point
constexpr float kBoundsMargin = 1.01f;   // grow fitted volumes so border texels are inside
constexpr float kPointFaceFovDeg = 90.0f;
// A fitted sun view is kept when its texels are at least this many times smaller.
constexpr float kMinSunRefinement = 1.5f;
// Around the visible samples: this fraction of the fitted square on each side (the surface
// between two samples, up to a grid step, may reach further out).
constexpr float kFitMargin = 0.08f;
// Sizes a fitted sun view may take per halving of its size (fitSunView).
constexpr float kFitSizeSteps = 4.0f;
// Samples left out at each end of each axis of the fit (fitSunView).
constexpr float kFitOutlierShare = 0.03f;

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
                            std::span<const Aabb> parts, int resolution) {
    LightCamera cam;
    cam.lightIndex = lightIndex;
    cam.origin = eye;
    cam.axis = glm::normalize(axis);
    cam.viewFromWorld = glm::lookAt(eye, eye + cam.axis, up);
    float nearM = 0.0f;
    float farM = 0.0f;
    computeDepthRange(bounds, parts, eye, cam.axis, nearM, farM);
    cam.clipFromView = glm::perspective(glm::radians(fovYDeg), 1.0f, nearM, farM);
    cam.texelPerDepth =
        2.0f * std::tan(glm::radians(fovYDeg) * 0.5f) / static_cast<float>(resolution);
    return cam;
}

} // namespace

std::vector<glm::vec3> sampleVisiblePoints(const BvhScene& bvh, const Scene& scene,
                                           const Camera& camera, float aspect, int raysPerSide) {
    const glm::mat4 worldFromView = glm::inverse(computeViewFromWorld(camera));
    const float tanHalf = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    std::vector<glm::vec3> points;
    for (int j = 0; j < raysPerSide; ++j) {
        for (int i = 0; i < raysPerSide; ++i) {
            // Cell centres of the image, in [-1, 1].
            const float x =
                (2.0f * (float(i) + 0.5f) / float(raysPerSide) - 1.0f) * tanHalf * aspect;
            const float y = (2.0f * (float(j) + 0.5f) / float(raysPerSide) - 1.0f) * tanHalf;
            Ray ray;
            ray.origin = camera.position;
            ray.direction = glm::normalize(glm::vec3(worldFromView * glm::vec4(x, y, -1.0f, 0.0f)));
            if (const std::optional<Hit> hit = intersect(bvh, scene, ray))
                points.push_back(ray.origin + hit->t * ray.direction);
        }
    }
    return points;
}

std::optional<LightCamera> fitSunView(const LightCamera& sun, const std::vector<glm::vec3>& visible,
                                      int resolution) {
    if (!sun.isOrthographic || visible.empty()) return std::nullopt;
    // Per axis, the samples between two quantiles: a few far points (the yard seen through a
    // door) would widen the square for all; the shadow test takes the sun's own view for them.
    std::array<std::vector<float>, 2> axes;
    for (const glm::vec3& p : visible) {
        const glm::vec2 v(sun.viewFromWorld * glm::vec4(p, 1.0f));
        axes[0].push_back(v.x);
        axes[1].push_back(v.y);
    }
    const auto trimmed = size_t(kFitOutlierShare * float(visible.size()));
    glm::vec2 lo(0.0f);
    glm::vec2 hi(0.0f);
    for (int a = 0; a < 2; ++a) {
        std::vector<float>& values = axes[size_t(a)];
        std::sort(values.begin(), values.end());
        lo[a] = values[trimmed];
        hi[a] = values[values.size() - 1 - trimmed];
    }
    const float fitted = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y) * (1.0f + 2.0f * kFitMargin) +
                         sun.texelSizeM; // at least a texel of the sun's own around a lone point
    const float sunHalf = 0.5f * sun.texelSizeM * float(resolution);
    if (fitted * kMinSunRefinement > sunHalf) return std::nullopt;
    // Stable under small changes (an object moving, the camera creeping): the size rounded up to
    // sunHalf / 2^(k / kFitSizeSteps), the centre snapped to whole texels, so shadow edges stay
    // on the same texel grid from frame to frame instead of crawling.
    const float steps = std::floor(-std::log2(fitted / sunHalf) * kFitSizeSteps);
    const float half = sunHalf * std::exp2(-steps / kFitSizeSteps);
    const float texel = 2.0f * half / float(resolution);
    const glm::vec2 centre = glm::round(0.5f * (lo + hi) / texel) * texel;
    LightCamera fine = sun;
    fine.isShadowOnly = true;
    // The sun's projection (a square of sunHalf around its axis) narrowed to the fitted square in
    // x and y; depth as it was.
    const float zoom = sunHalf / half;
    fine.clipFromView = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-centre / half, 0.0f)),
                                   glm::vec3(zoom, zoom, 1.0f)) *
                        sun.clipFromView;
    fine.texelSizeM = texel;
    return fine;
}

void computeDepthRange(const Aabb& bounds, std::span<const Aabb> parts, const glm::vec3& eye,
                       const glm::vec3& axis, float& nearM, float& farM) {
    float maxDepth = 0.0f;
    for (const glm::vec3& c : getCorners(bounds))
        maxDepth = std::max(maxDepth, glm::dot(c - eye, axis));
    const float diagonal = 2.0f * glm::length(bounds.getExtent());
    farM = std::max({maxDepth * kBoundsMargin, diagonal * kMinFarFraction,
                     std::numeric_limits<float>::min() / kNearFraction});
    // The near plane must not clip anything in front of the eye: keep it small.
    nearM = farM * kNearFraction;
    for (const Aabb& part : parts) {
        float partFar = 0.0f;
        for (const glm::vec3& c : getCorners(part))
            partFar = std::max(partFar, glm::dot(c - eye, axis) * kBoundsMargin);
        if (!(partFar > 0.0f)) continue; // wholly behind the eye
        const glm::vec3 nearest = glm::clamp(eye, part.lo, part.hi);
        const float distance = glm::length(nearest - eye); // 0 inside
        nearM = std::min(nearM, std::max(0.5f * distance, partFar * kNearFraction));
    }
}

std::vector<LightCamera> computeLightCameras(const Scene& scene, int resolution) {
    const std::vector<Aabb> parts = scene.computeInstanceBounds();
    const Aabb bounds = computeUnion(parts);
    std::vector<LightCamera> cameras;
    for (uint32_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        switch (light.type) {
        case LightType::Spot: {
            const glm::vec3 axis = glm::normalize(light.direction);
            cameras.push_back(makePerspective(i, light.position, axis, pickUp(axis),
                                              2.0f * light.outerDeg, bounds, parts, resolution));
            break;
        }
        case LightType::Point: {
            // Cube faces in the usual +x, -x, +y, -y, +z, -z order.
            const glm::vec3 axes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
            for (const glm::vec3& axis : axes) {
                cameras.push_back(makePerspective(i, light.position, axis, pickUp(axis),
                                                  kPointFaceFovDeg, bounds, parts, resolution));
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
            // A footprint however small the scene (a floor in metres would outgrow a tiny one).
            halfSize = std::max(halfSize * kBoundsMargin, kMinFootprintM);
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

std::optional<Aabb> computeLitBounds(const Light& light, const Aabb& sceneBounds) {
    if (light.type != LightType::Spot || !(light.outerDeg < kMaxBoundedSpotDeg))
        return std::nullopt;
    if (sceneBounds.isEmpty()) return Aabb{};
    const glm::vec3 axis = glm::normalize(light.direction);
    // A lit point p has t = dot(p - apex, axis) >= |p - apex| cos(outer) and lies within
    // t tan(outer) of the axis: inside the cone of height `reach`, the farthest the scene's box
    // extends along the axis, which is the hull of the apex and the disc that caps it.
    float reach = 0.0f;
    for (int i = 0; i < kAabbCornerCount; ++i)
        reach = std::max(reach, glm::dot(sceneBounds.getCorner(i) - light.position, axis));
    if (reach <= 0.0f) return Aabb{}; // the scene lies behind the light
    const glm::vec3 capCentre = light.position + axis * reach;
    const float capRadius = reach * std::tan(glm::radians(std::max(light.outerDeg, 0.0f)));
    // A disc of radius r and unit normal a reaches r sqrt(1 - a_i^2) along axis i.
    const glm::vec3 capHalf = capRadius * glm::sqrt(glm::max(glm::vec3(1.0f) - axis * axis, 0.0f));
    Aabb cone;
    cone.extend(light.position);
    cone.extend(capCentre - capHalf);
    cone.extend(capCentre + capHalf);
    Aabb lit;
    lit.lo = glm::max(cone.lo, sceneBounds.lo);
    lit.hi = glm::min(cone.hi, sceneBounds.hi);
    if (glm::any(glm::lessThan(lit.hi, lit.lo))) return Aabb{};
    return lit;
}

} // namespace ispm
