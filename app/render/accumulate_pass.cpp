// Accumulation: one full-screen draw mixing this frame's indirect light into the history, then a
// copy of the result into the history for the next frame.
#include "render/accumulate_pass.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <shared/scene_data.h>

namespace ispm {
namespace {

constexpr GLint kLocationWeight = 0; // shaders/denoise/accumulate.frag

} // namespace

float computeAccumulateWeight(int accumulate, uint32_t historyFrames) {
    if (accumulate <= 0) return 1.0f;
    return 1.0f / static_cast<float>(historyFrames + 1); // a full history is never drawn to
}

AccumulatePass::AccumulatePass(const gl::Texture& direct, const gl::Texture& indirect)
    : mProgram(
          ReloadableProgram({.label = "accumulate",
                             .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                        {gl::ShaderStage::Fragment, "denoise/accumulate.frag"}}})),
      mVertexArray("accumulate vao"),
      mLights({Light{direct, ColorTarget("direct (accumulated)", gl::Format::RGBA32F), {}},
               Light{indirect, ColorTarget("indirect (accumulated)", gl::Format::RGBA32F), {}}}) {}

void AccumulatePass::resize(int width, int height) {
    for (size_t i = 0; i < mLights.size(); ++i) {
        Light& light = mLights[i];
        light.target.resize(width, height);
        if (light.history.getWidth() == width && light.history.getHeight() == height) continue;
        light.history = gl::Texture::create2D(i == kDirect ? "direct history" : "indirect history",
                                              gl::Format::RGBA32F, width, height);
    }
}

void AccumulatePass::execute(const FrameInputs& inputs) {
    const float weight = computeAccumulateWeight(inputs.settings.accumulate, inputs.historyFrames);
    for (Light& light : mLights) {
        if (weight >= 1.0f) {
            light.target.getTexture().copyFrom(light.current); // no history to mix with
        } else {
            light.target.bind();
            gl::applyState({});
            mProgram.use();
            mVertexArray.bind();
            light.current.bindUnit(gpu::kUnitFilterSource);
            light.history.bindUnit(gpu::kUnitHistory);
            glUniform1f(kLocationWeight, weight);
            drawFullscreenTriangle();
        }
        if (inputs.settings.accumulate > 0) light.history.copyFrom(light.target.getTexture());
    }
}

} // namespace ispm
