// The shape every render pass shares: a name for timers and debug groups, execute() for the
// frame, resize() when the output size changes. Inputs arrive through FrameInputs, outputs are
// the pass's own resources, read through its getters.
#pragma once

#include "gl/objects.h"
#include "render/reloadable_program.h"
#include "settings/frame_settings.h"

#include <shared/scene_data.h>

#include <glm/glm.hpp>

namespace ispm {

class GpuScene;
struct Scene;

// How frame `historyFrames` of an accumulation estimates its light (computeProgressiveStep):
// as more frames are averaged, bias matters more than one frame's noise.
struct ProgressiveStep {
    float radiusFactor = 1.0f;       // multiplies every splat radius
    float neighbourFactor = 1.0f;    // multiplies splat_neighbours (radius_mode density)
    float travelRadiusFactor = 0.0f; // density radii at most this times the photon's travel; 0: off
    // A density radius measures a photon against its neighbours' mean power, so a much stronger
    // one spreads wide (one frame's noise); off, its own power counts in the density (less blur
    // for averaged frames, whose noise the average takes down).
    bool spreadStrongPhotons = true;
    int denoiseIterations = 0; // a-trous iterations of this frame
};

// "SHADOW_RAYS 1" with shadows ray, else "SHADOW_RAYS 0": the direct and importance programs'
// variant (their shadow test, lib/shadow_rays.glsl or the shadow maps).
inline const char* getShadowRaysDefine(const FrameSettings& settings) {
    return settings.shadows == gpu::kShadowsRay ? "SHADOW_RAYS 1" : "SHADOW_RAYS 0";
}

// What a frame hands every pass.
struct FrameInputs {
    const Scene& model; // the scene model (lights, materials) the GPU scene was made from
    const GpuScene& scene;
    const FrameSettings& settings;    // resolved once per settings change
    const gl::Buffer& frameConstants; // gpu::FrameConstants, bound at kBindingFrameConstants
    glm::mat4 clipFromWorld{1.0f};
    glm::vec3 cameraPosition{0.0f};
    int width = 0;
    int height = 0;
    // Frames of this still view accumulated before this one: 0 after a move or a reset
    // (AccumulatePass, the progressive step, the sub-pixel offsets).
    uint32_t historyFrames = 0;
    // The accumulated light is stale (a light, a setting or the scene changed): start anew.
    bool historyReset = true;
    // The camera or an object moved since the last frame: the history is reprojected.
    bool moved = false;
    glm::mat4 previousClipFromWorld{1.0f}; // the last frame's camera, its sub-pixel offset included
    // This frame's random seed: `seed`, moved on with every frame drawn since the last reset
    // while accumulating, so every accumulated frame traces new photons.
    uint32_t seed = 0;
    ProgressiveStep progressive; // this frame's place in the accumulation
    // Draws the splat is split into (the trace pass writes their commands): splat_passes, or
    // more when the frame is drawn in slices (FrameRunner::beginFrame); at most kMaxSplatDraws.
    uint32_t splatDraws = 1;

    // Every splat radius's factor: radius_scale, times the shrink of accumulated frames.
    float getRadiusScale() const { return settings.radiusScale * progressive.radiusFactor; }
};

class Pass {
  public:
    virtual ~Pass() = default;
    virtual const char* getName() const = 0;
    virtual void resize(int width, int height) {
        (void)width;
        (void)height;
    }
    virtual void execute(const FrameInputs& inputs) = 0;
    // Rebuilds the programs whose source files changed (the viewer's F5); see ReloadableProgram.
    virtual void reloadPrograms(ShaderReloadReport& report) = 0;
};

} // namespace ispm
