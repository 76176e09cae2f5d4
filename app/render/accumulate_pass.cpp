// Accumulation: one full-screen draw mixing this frame's indirect light into the history, then a
// copy of the result into the history for the next frame.
#include "render/accumulate_pass.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <shared/scene_data.h>

#include <algorithm>

namespace ispm {
namespace {

constexpr GLint kLocationWeight = 0; // shaders/denoise/accumulate.frag

} // namespace

float computeAccumulateWeight(int accumulate, uint32_t historyFrames) {
    if (accumulate <= 0 || historyFrames == 0) return 1.0f;
    const uint32_t window = std::min(historyFrames + 1, static_cast<uint32_t>(accumulate));
    return 1.0f / static_cast<float>(window);
}

AccumulatePass::AccumulatePass(const gl::Texture& current)
    : mCurrent(current),
      mProgram(ReloadableProgram({.label = "accumulate",
                                  .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                             {gl::ShaderStage::Fragment, "denoise/accumulate.frag"}}})),
      mVertexArray("accumulate vao"), mTarget("indirect (accumulated)", gl::Format::RGBA32F) {}

void AccumulatePass::resize(int width, int height) {
    mTarget.resize(width, height);
    if (mHistory.getWidth() == width && mHistory.getHeight() == height) return;
    mHistory = gl::Texture::create2D("indirect history", gl::Format::RGBA32F, width, height);
}

void AccumulatePass::execute(const FrameInputs& inputs) {
    const float weight = computeAccumulateWeight(inputs.settings.accumulate, inputs.historyFrames);
    if (weight >= 1.0f) {
        mTarget.getTexture().copyFrom(mCurrent); // no history to mix with
    } else {
        mTarget.bind();
        gl::applyState({});
        mProgram.use();
        mVertexArray.bind();
        mCurrent.bindUnit(gpu::kUnitFilterSource);
        mHistory.bindUnit(gpu::kUnitHistory);
        glUniform1f(kLocationWeight, weight);
        drawFullscreenTriangle();
    }
    if (inputs.settings.accumulate > 0) mHistory.copyFrom(mTarget.getTexture());
}

} // namespace ispm
