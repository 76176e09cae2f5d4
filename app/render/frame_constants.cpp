// The per-frame constants of a camera: view and projection, image size, lights, tone map.
#include "render/frame_constants.h"

#include <algorithm>
#include <cmath>

namespace ispm {

void computeCameraRange(const Camera& camera, const Aabb& bounds, float& nearM, float& farM) {
    const glm::vec3 axis = glm::normalize(camera.target - camera.position);
    computeDepthRange(bounds, camera.position, axis, nearM, farM);
    // The viewer's frustum corners reach further than its axis: grow far for the widest ray.
    const float halfDiagonal = glm::length(bounds.getExtent());
    farM = std::max(farM, glm::length(bounds.getCenter() - camera.position) + halfDiagonal);
    if (camera.nearM > 0.0f) nearM = camera.nearM;
    if (camera.farM > 0.0f) farM = camera.farM;
}

gpu::FrameConstants computeFrameConstants(const Scene& scene, const GpuScene& gpuScene,
                                          const FrameSettings& settings, int width, int height) {
    const Camera& cam = scene.camera;
    float nearM = 0.0f;
    float farM = 0.0f;
    computeCameraRange(cam, gpuScene.getBounds(), nearM, farM);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    gpu::FrameConstants fc{};
    fc.clipFromWorld = computeClipFromView(cam, aspect, nearM, farM) * computeViewFromWorld(cam);
    fc.worldFromClip = glm::inverse(fc.clipFromWorld);
    fc.cameraPosition = glm::vec4(cam.position, 1.0f);
    fc.background = glm::vec4(scene.background, 0.0f);
    fc.imageSize = glm::vec4(width, height, 1.0f / static_cast<float>(width),
                             1.0f / static_cast<float>(height));
    fc.counts = glm::uvec4(gpuScene.getLightCount(),
                           static_cast<uint32_t>(gpuScene.getLightCameras().size()),
                           settings.seed, settings.toneMap);
    fc.shadow = glm::vec4(settings.shadowBiasTexels,
                          static_cast<float>(gpuScene.getLightResolution()), 0.0f, 0.0f);
    fc.tonemap = glm::vec4(0.0f, std::exp2(settings.exposureStops), 1.0f / settings.gamma,
                           settings.luminanceMax.value_or(0.0f));
    return fc;
}

} // namespace ispm
