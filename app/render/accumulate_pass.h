// AccumulatePass: temporal accumulation of the indirect light while nothing moves. Each frame
// traces new photons (FrameRunner shifts the seed by the frame count), and this pass averages
// their light into a history: a running mean over the first `accumulate` frames, then an
// exponential mean over that many. FrameRunner restarts the history (frame count 0) when the
// camera, the scene, a light or a setting changes, so no stale light outlives a change by a
// frame. With `accumulate` 0 the frame's light passes through. Its output is the indirect AOV.
#pragma once

#include "render/fullscreen.h"
#include "render/pass.h"

namespace ispm {

// The weight of this frame's light: 1 / (frames + 1) while the history holds fewer than
// `accumulate` frames, then 1 / accumulate; 1 when accumulation is off or the history is empty.
float computeAccumulateWeight(int accumulate, uint32_t historyFrames);

class AccumulatePass final : public Pass {
public:
    explicit AccumulatePass(const gl::Texture& current);
    const char* getName() const override { return "accumulate"; }
    void resize(int width, int height) override;
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override { mProgram.reloadIfChanged(report); }
    const gl::Texture& getOutput() const { return mTarget.getTexture(); }

private:
    const gl::Texture& mCurrent;
    ReloadableProgram mProgram;
    gl::VertexArray mVertexArray;
    ColorTarget mTarget;    // this frame's average
    gl::Texture mHistory;   // the previous frame's average
};

} // namespace ispm
