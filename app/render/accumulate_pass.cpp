// Accumulation: one full-screen draw mixing this frame's direct and indirect light into their
// histories, then a copy of the result into the history for the next frame.
#include "render/accumulate_pass.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <shared/scene_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

constexpr GLint kLocationWeight = 0; // shaders/denoise/accumulate.frag

// Progressive photon mapping's alpha, the share of the photons a shrinking radius keeps (Hachisuka
// et al. 2008 use 2/3 for an unbounded sequence). Measured over 32 frames of the Cornell box and
// both courtyard views (README, "Converging and moving"): 0.8 gives the lowest error; 2/3 shrinks
// too fast for so few frames (noise), 1 keeps the blur.
constexpr double kProgressiveAlpha = 0.8;
// Density radius at most this times the photon's travel (computeProgressiveStep). Measured as
// alpha: 0.25 to 2 all help outdoors, 0.5 the most.
constexpr float kTravelRadiusFactor = 0.5f;

} // namespace

float computeAccumulateWeight(int accumulate, uint32_t historyFrames) {
    if (accumulate <= 0) return 1.0f;
    return 1.0f / static_cast<float>(historyFrames + 1); // a full history is never drawn to
}

ProgressiveStep computeProgressiveStep(int accumulate, uint32_t historyFrames,
                                       int denoiseIterations) {
    ProgressiveStep step;
    step.denoiseIterations = denoiseIterations;
    if (accumulate <= 0 || historyFrames == 0) return step;
    double squared = 1.0;
    for (uint32_t j = 0; j < historyFrames; ++j)
        squared *= (double(j) + kProgressiveAlpha) / (double(j) + 1.0);
    step.radiusFactor = float(std::sqrt(squared));
    step.travelRadiusFactor = kTravelRadiusFactor;
    int fewer = 0;
    for (uint64_t frames = 4; frames <= uint64_t(historyFrames) + 1; frames *= 4)
        ++fewer;
    step.denoiseIterations = std::max(denoiseIterations - fewer, 0);
    return step;
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
