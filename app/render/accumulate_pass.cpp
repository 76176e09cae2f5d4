// Accumulation: one full-screen draw mixing this frame's direct and indirect light into their
// histories, then copies of the results and of the G-buffer's surface for the next frame.
#include "render/accumulate_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/fullscreen.h"
#include "render/gpu_scene.h"

#include <shared/photon_scatter.h> // kRngPerFrame
#include <shared/scene_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// Frames that light averaged while moving counts for when the view comes to rest
// (computeHistoryCap): enough that the first still frames add their noise to a smooth image, few
// enough that after `accumulate` still frames it weighs 4 / (accumulate + 4) (11% at 32).
constexpr uint32_t kMovingFramesCarried = 4;

// Progressive photon mapping's alpha, the share of the photons a shrinking radius keeps (Hachisuka
// et al. 2008 use 2/3 for an unbounded sequence). Measured over 32 frames of the Cornell box and
// both courtyard views (docs/results.md, "Converging and moving"): 0.8 gives the lowest error;
// 2/3 shrinks too fast for so few frames (noise), 1 keeps the blur.
constexpr double kProgressiveAlpha = 0.8;
// Density radius at most this times the photon's travel (computeProgressiveStep). Measured as
// alpha: 0.25 to 2 all help outdoors, 0.5 the most; in one frame too (courtyard outside, median
// of six seeds, 0.272 -> 0.263; Cornell box and room unchanged).
constexpr float kTravelRadiusFactor = 0.5f;
// Accumulated frames from the second on hold this share of splat_neighbours: one frame's discs
// are wide for its noise, which the average takes down, while their blur stays. 32 frames of the
// Cornell box, courtyard outside and room (rel RMSE 4x4), one frame holding 0.3 sqrt(photons):
// 0.053 / 0.093 / 0.099 at 0.367 (0.11 sqrt(photons), the earlier rule), 0.051 / 0.090 / 0.091
// at 0.55, the same at 0.75. One frame now holds 0.45 sqrt(photons): the share keeps 0.165
// sqrt(photons).
constexpr double kAveragedNeighbourShare = 0.55 * 0.3 / 0.45;

} // namespace

float computeAccumulateWeight(int accumulate, uint32_t historyFrames) {
    if (accumulate <= 0) return 1.0f;
    return 1.0f / static_cast<float>(historyFrames + 1); // a full history is never drawn to
}

float computeHistoryCap(const FrameInputs& inputs) {
    const int accumulate = inputs.settings.accumulate;
    if (accumulate <= 0 || inputs.historyReset) return 0.0f;
    if (inputs.moved) return float(accumulate - 1);
    return float(inputs.historyFrames + kMovingFramesCarried);
}

ProgressiveStep computeProgressiveStep(int accumulate, uint32_t historyFrames,
                                       int denoiseIterations) {
    ProgressiveStep step;
    step.denoiseIterations = denoiseIterations;
    step.travelRadiusFactor = kTravelRadiusFactor;
    if (accumulate <= 0 || historyFrames == 0) return step;
    double squared = 1.0;
    for (uint32_t j = 0; j < historyFrames; ++j)
        squared *= (double(j) + kProgressiveAlpha) / (double(j) + 1.0);
    step.radiusFactor = float(std::sqrt(squared));
    step.neighbourFactor = float(kAveragedNeighbourShare);
    step.spreadStrongPhotons = false;
    int fewer = 0;
    for (uint64_t frames = 4; frames <= uint64_t(historyFrames) + 1; frames *= 4)
        ++fewer;
    step.denoiseIterations = std::max(denoiseIterations - fewer, 0);
    return step;
}

void AccumulationHistory::restart() {
    mReset = true;
    mFrames = 0;
    mSequenceFrames = 0;
}

bool AccumulationHistory::setCamera(const Camera& camera) {
    const bool moved = !isSameCamera(camera, mCamera);
    if (moved) {
        mFrames = 0;
        mMoved = true;
    }
    mCamera = camera;
    return moved;
}

void AccumulationHistory::setSceneUpdated(uint64_t lightsVersion) {
    if (lightsVersion != mLightsVersion) {
        restart(); // the light itself changed: everything drawn before is stale
        return;
    }
    mFrames = 0;
    mMoved = true;
}

void AccumulationHistory::addFrame(const glm::mat4& clipFromWorld, uint64_t lightsVersion) {
    mPreviousClipFromWorld = clipFromWorld;
    mLightsVersion = lightsVersion;
    mReset = false;
    mMoved = false;
    ++mFrames;
    ++mSequenceFrames;
    ++mFramesDrawn;
}

uint32_t AccumulationHistory::computeSeed(const FrameSettings& settings) const {
    // per_frame: new numbers every frame drawn (the thesis's prototype); the others keep them
    // while the view holds, and move on only to add frames to an accumulation.
    if (settings.rngMode == gpu::kRngPerFrame) return settings.seed + mFramesDrawn;
    return settings.accumulate > 0 ? settings.seed + mSequenceFrames : settings.seed;
}

AccumulatePass::AccumulatePass(const GBuffer& viewer, const gl::Texture& direct,
                               const gl::Texture& indirect)
    : mViewer(viewer), mDirect(direct), mIndirect(indirect),
      mProgram(
          ReloadableProgram({.label = "accumulate",
                             .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                        {gl::ShaderStage::Fragment, "denoise/accumulate.frag"}},
                             .defines = getGBufferDefines()})),
      mVertexArray("accumulate vao") {}

void AccumulatePass::resize(int width, int height) {
    if (mOutputs[kDirect].getWidth() == width && mOutputs[kDirect].getHeight() == height) return;
    constexpr std::array<const char*, 3> kNames = {"direct", "indirect", "history length"};
    for (size_t i = 0; i < mOutputs.size(); ++i) {
        const gl::Format format = i == kLength ? gl::Format::R32F : gl::Format::RGBA32F;
        const std::string name = kNames[i];
        mOutputs[i] = gl::Texture::create2D(name + " (accumulated)", format, width, height);
        mHistory[i] = gl::Texture::create2D(name + " history", format, width, height);
    }
    mHistoryPosition =
        gl::Texture::create2D("history position", gl::Format::RGBA32F, width, height);
    mHistoryNormal = gl::Texture::create2D("history normal", gl::Format::RGBA16F, width, height);
    mFramebuffer = gl::Framebuffer("accumulate target");
    for (size_t i = 0; i < mOutputs.size(); ++i)
        mFramebuffer.attachColor(static_cast<int>(i), mOutputs[i]);
    mFramebuffer.setDrawBufferCount(static_cast<int>(mOutputs.size()));
    mFramebuffer.checkComplete();
}

void AccumulatePass::execute(const FrameInputs& inputs) {
    const int accumulate = inputs.settings.accumulate;
    if (accumulate <= 0) {
        mOutputs[kDirect].copyFrom(mDirect); // no history to mix with
        mOutputs[kIndirect].copyFrom(mIndirect);
    } else {
        mixIntoHistory(inputs);
    }
    mWindow = uint32_t(std::max(accumulate, 1));
    mState.addFrame(inputs.clipFromWorld, inputs.scene.getLightsVersion());
}

void AccumulatePass::mixIntoHistory(const FrameInputs& inputs) {
    const int accumulate = inputs.settings.accumulate;
    mFramebuffer.bind();
    gl::applyState({});
    mProgram.use();
    mVertexArray.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    inputs.scene.bind(); // instances and their previous transforms
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mDirect.bindUnit(gpu::kUnitDirect);
    mIndirect.bindUnit(gpu::kUnitIndirect);
    mHistory[kDirect].bindUnit(gpu::kUnitHistoryDirect);
    mHistory[kIndirect].bindUnit(gpu::kUnitHistoryIndirect);
    mHistory[kLength].bindUnit(gpu::kUnitHistoryLength);
    mHistoryPosition.bindUnit(gpu::kUnitHistoryPosition);
    mHistoryNormal.bindUnit(gpu::kUnitHistoryNormal);
    gpu::AccumulateParams params{};
    params.previousClipFromWorld = inputs.previousClipFromWorld;
    params.directWeight = computeAccumulateWeight(accumulate, inputs.historyFrames);
    params.historyCapFrames = computeHistoryCap(inputs); // after a reset the cap is 0
    params.moved = inputs.moved ? 1u : 0u;
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    drawFullscreenTriangle();
    for (size_t i = 0; i < mOutputs.size(); ++i)
        mHistory[i].copyFrom(mOutputs[i]);
    mHistoryPosition.copyFrom(mViewer.getChannel("position"));
    mHistoryNormal.copyFrom(mViewer.getChannel("normal"));
}

} // namespace ispm
