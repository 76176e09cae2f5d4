// The per-frame constants of a camera: view and projection, image size, lights, tone map.
#include "render/frame_constants.h"

#include "core/strings.h"
#include "scene/json_reader.h"

#include <shared/specular_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {

void computeCameraRange(const Camera& camera, const Aabb& bounds, std::span<const Aabb> parts,
                        float& nearM, float& farM) {
    const glm::vec3 axis = glm::normalize(camera.target - camera.position);
    computeDepthRange(bounds, parts, camera.position, axis, nearM, farM);
    // The viewer's frustum corners reach further than its axis: grow far for the widest ray.
    const float halfDiagonal = glm::length(bounds.getExtent());
    farM = std::max(farM, glm::length(bounds.getCenter() - camera.position) + halfDiagonal);
    if (camera.farM > 0.0f) farM = std::min(camera.farM, farM);
    if (camera.nearM > 0.0f) nearM = std::max(camera.nearM, farM * kMinNearToFar);
    nearM = std::min(nearM, farM * 0.5f); // a near plane set past the scene still leaves a range
}

std::string describeRaisedNearPlane(const Camera& camera, const Aabb& bounds,
                                    std::span<const Aabb> parts) {
    if (!(camera.nearM > 0.0f)) return "";
    float nearM = 0.0f;
    float farM = 0.0f;
    computeCameraRange(camera, bounds, parts, nearM, farM);
    if (nearM == camera.nearM) return "";
    return strCat("the camera's near plane (", formatFloat(camera.nearM), " m) is ", "raised to ",
                  formatFloat(nearM), " m, 1e-5 of the far plane (", formatFloat(farM),
                  " m): a 32-bit depth buffer cannot order depths over a wider range");
}

namespace {

float computeRadicalInverse(uint32_t index, uint32_t base) {
    float inverse = 0.0f;
    float digit = 1.0f / static_cast<float>(base);
    for (uint32_t i = index; i > 0; i /= base) {
        inverse += static_cast<float>(i % base) * digit;
        digit /= static_cast<float>(base);
    }
    return inverse;
}

// Point `frame` of the Halton sequence in bases (x, y), centred: in [-0.5, 0.5)^2, 0 for frame 0.
glm::vec2 computeHaltonOffset(uint32_t frame, uint32_t baseX, uint32_t baseY) {
    if (frame == 0) return glm::vec2(0.0f);
    return glm::vec2(computeRadicalInverse(frame, baseX), computeRadicalInverse(frame, baseY)) -
           0.5f;
}

} // namespace

glm::vec2 computePixelJitter(uint32_t frame) {
    return computeHaltonOffset(frame, 2, 3);
}

glm::vec2 computeFrameJitter(const FrameSettings& settings, uint32_t historyFrames) {
    return settings.accumulate > 0 ? computePixelJitter(historyFrames) : glm::vec2(0.0f);
}

glm::vec2 computeShadowJitter(uint32_t frame) {
    return computeHaltonOffset(frame, 5, 7);
}

gpu::FrameConstants computeFrameConstants(const Scene& scene, const GpuScene& gpuScene,
                                          const FrameSettings& settings, int width, int height,
                                          uint32_t seed, glm::vec2 jitterPx) {
    const Camera& cam = scene.camera;
    float nearM = 0.0f;
    float farM = 0.0f;
    computeCameraRange(cam, gpuScene.getBounds(), gpuScene.getInstanceBounds(), nearM, farM);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    gpu::FrameConstants fc{};
    const glm::mat4 clipFromView = computeClipShift(jitterPx, glm::vec2(width, height)) *
                                   computeClipFromView(cam, aspect, nearM, farM);
    const glm::mat4 viewFromWorld = computeViewFromWorld(cam);
    fc.clipFromWorld = clipFromView * viewFromWorld;
    fc.worldFromClip = glm::inverse(fc.clipFromWorld);
    fc.eyeOffsetFromClip = glm::inverse(clipFromView * glm::mat4(glm::mat3(viewFromWorld)));
    fc.cameraPosW = cam.position;
    fc.lightCount = gpuScene.getLightCount();
    fc.backgroundRadiance = scene.background;
    fc.lightViewCount = static_cast<uint32_t>(gpuScene.getLightCameras().size());
    fc.imageSizePx = glm::vec2(width, height);
    fc.inverseImageSizePx =
        glm::vec2(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height));
    fc.seed = seed;
    fc.tonemapOperator = settings.toneMap;
    fc.shadowBiasTexels = settings.shadowBiasTexels;
    fc.lightResolutionPx = static_cast<float>(gpuScene.getLightResolution());
    fc.adaptationWeight = 0.0f;
    fc.exposureScale = std::exp2(settings.exposureStops);
    fc.inverseGamma = 1.0f / settings.gamma;
    fc.luminanceMax = settings.luminanceMax.value_or(0.0f);
    fc.specularTraceMinExponent =
        settings.specularDepth > 0 && settings.bounces > 0 ? gpu::kSpecularTraceMinExponent : 0.0f;
    fc.emitterCount = gpuScene.getEmitterCount();
    fc.emitterWeight = float(gpuScene.getEmitters().totalWeight);
    fc.areaSamples = uint32_t(settings.areaSamples);
    return fc;
}

} // namespace ispm
