// AccumulatePass: temporal accumulation of the direct and indirect light while nothing moves.
// Each frame traces new photons and looks through a new sub-pixel offset of the camera
// (FrameRunner moves the seed and the jitter on with the frame count), and this pass averages
// both lights into their histories: a running mean over `accumulate` frames, after which
// FrameRunner draws nothing more (the image holds). FrameRunner restarts the histories (frame
// count 0) when the camera, the scene, a light or a setting changes, so no stale light outlives
// a change by a frame. With `accumulate` 0 the frame's light passes through. Its outputs are the
// direct and indirect AOVs.
#pragma once

#include "render/fullscreen.h"
#include "render/pass.h"

#include <array>

namespace ispm {

// The weight of this frame's light: 1 / (frames + 1), a running mean (FrameRunner draws no
// frame once the history holds `accumulate`); 1 when accumulation is off or the history empty.
float computeAccumulateWeight(int accumulate, uint32_t historyFrames);

// Frame `historyFrames` of an accumulation (`accumulate` > 0); frame 0 and every frame without
// accumulation get the settings' radii and `denoiseIterations`.
// - Radii shrink as frames are averaged, as in progressive photon mapping (Knaus and Zwicker
//   2011): frame i's squared radius is frame 0's times prod_{j<i} (j + alpha) / (j + 1), about
//   i^(alpha - 1), so that the average's blur (bias ~ r^2) and noise (variance ~ 1 / (i r^2))
//   both go to zero.
// - From frame 1 on, a density radius is at most kTravelRadiusFactor times the photon's travel:
//   light that came from a surface at distance d varies over about d (a wall's foot, a concave
//   corner), which one frame's neighbour count blurs; the average pays for the extra noise.
// - The average's noise variance falls as 1 / frames and each a-trous iteration widens the
//   filter 2x (4x its area): one iteration fewer for every 4x frames.
ProgressiveStep computeProgressiveStep(int accumulate, uint32_t historyFrames,
                                       int denoiseIterations);

class AccumulatePass final : public Pass {
  public:
    AccumulatePass(const gl::Texture& direct, const gl::Texture& indirect);
    const char* getName() const override { return "accumulate"; }
    void resize(int width, int height) override;
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override { mProgram.reloadIfChanged(report); }
    const gl::Texture& getDirect() const { return mLights[kDirect].target.getTexture(); }
    const gl::Texture& getIndirect() const { return mLights[kIndirect].target.getTexture(); }

  private:
    static constexpr size_t kDirect = 0;
    static constexpr size_t kIndirect = 1;
    struct Light {
        const gl::Texture& current;
        ColorTarget target;  // this frame's average
        gl::Texture history; // the previous frame's average
    };
    ReloadableProgram mProgram;
    gl::VertexArray mVertexArray;
    std::array<Light, 2> mLights;
};

} // namespace ispm
