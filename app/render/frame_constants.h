// Per-frame constants (gpu::FrameConstants) of the scene's camera, shared by the photon mapper
// and the reference path tracer so that both see the same camera.
#pragma once

#include "render/gpu_scene.h"
#include "scene/frame_settings.h"
#include "scene/scene.h"

#include <shared/scene_data.h>

namespace ispm {

// Camera clip planes when the scene does not set them: enclose the scene bounds.
void computeCameraRange(const Camera& camera, const Aabb& bounds, float& nearM, float& farM);

// The per-frame constants of the scene's camera at width x height (shared by the photon mapper
// and the reference path tracer, so both see the same camera).
// `seed` is the frame's (FrameInputs::seed); `jitterPx` shifts the image by a fraction of a
// pixel (accumulated frames sample the pixel).
gpu::FrameConstants computeFrameConstants(const Scene& scene, const GpuScene& gpuScene,
                                          const FrameSettings& settings, int width, int height,
                                          uint32_t seed, glm::vec2 jitterPx = glm::vec2(0.0f));

// The sub-pixel offset of accumulated frame `frame` in [-0.5, 0.5)^2 pixels: none for frame 0,
// then the Halton (2, 3) sequence, so that N frames cover the pixel evenly.
glm::vec2 computePixelJitter(uint32_t frame);
// The sub-pixel offset a frame looks through: computePixelJitter while accumulating, else none.
glm::vec2 computeFrameJitter(const FrameSettings& settings, uint32_t historyFrames);

// The light cameras' offset for accumulated frame `frame`, in texels of their G-buffers:
// (Halton 5, 7) - 1/2, none for frame 0. Bases apart from computePixelJitter's, so the two
// offsets do not move in step. The average of the frames' shadow tests is the visibility
// filtered over a texel: shadow edges come out where they are instead of on the texel grid.
glm::vec2 computeShadowJitter(uint32_t frame);

} // namespace ispm
