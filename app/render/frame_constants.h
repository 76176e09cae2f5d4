// Per-frame constants (gpu::FrameConstants) of the scene's camera, shared by the photon mapper
// and the reference path tracer so that both see the same camera.
#pragma once

#include "render/gpu_scene.h"
#include "scene/scene.h"
#include "settings/frame_settings.h"

#include <shared/scene_data.h>

#include <span>
#include <string>

namespace ispm {

// The camera's clip planes: where the scene does not set them, they enclose the scene bounds. A
// far plane set beyond those is brought in to them (nothing lies further), and a near plane
// under kMinNearToFar of the far one is raised to it: a 32-bit depth buffer cannot tell depths
// apart over a wider range, and everything would land on the far plane (a black image).
inline constexpr float kMinNearToFar = 1e-5f;
// `parts`: the instances' boxes (computeDepthRange).
void computeCameraRange(const Camera& camera, const Aabb& bounds, std::span<const Aabb> parts,
                        float& nearM, float& farM);
// One line for stderr when computeCameraRange raised the scene's near plane; "" otherwise.
std::string describeRaisedNearPlane(const Camera& camera, const Aabb& bounds,
                                    std::span<const Aabb> parts);

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
