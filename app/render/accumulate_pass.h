// AccumulatePass: temporal accumulation of the direct and indirect light. Each frame traces new
// photons, and while the view is still looks through a new sub-pixel offset of the camera
// (FrameRunner moves the seed and the offsets on); this pass mixes both lights into their
// histories:
// - while nothing moves, a running mean over `accumulate` frames, after which FrameRunner draws
//   nothing more (the image holds);
// - when the camera or objects move, the indirect history is reprojected (each pixel's surface
//   found where it was in the last frame, kept where the same surface is there) and averaged over
//   at most `accumulate` frames per pixel; the direct light starts anew (shadows move with
//   objects);
// - a light, a setting or the scene changed: both start anew, so no stale light outlives a change
//   by a frame.
// With `accumulate` 0 the frame's light passes through. Its outputs are the direct and indirect
// AOVs, and each pixel's history length.
#pragma once

#include "render/gbuffer.h"
#include "render/pass.h"
#include "scene/scene.h"

#include <shared/scene_data.h>

#include <algorithm>
#include <array>

namespace ispm {

// The weight of this frame's direct light: 1 / (frames + 1), a running mean of the still view
// (FrameRunner draws no frame once the history holds `accumulate`); 1 when accumulation is off or
// the history empty.
float computeAccumulateWeight(int accumulate, uint32_t historyFrames);

// How many earlier frames a pixel's indirect history may count for at most (its weight against
// this frame's): none after a reset; `accumulate` - 1 while moving (a running mean of that
// window); in a still view, frame i counts i + kMovingFramesCarried, so that light averaged while
// moving (full radii, reprojected) fades as the still frames come in, without a jump to one frame's
// noise. A still view from a reset counts every frame (its length is i): a plain running mean.
float computeHistoryCap(const FrameInputs& inputs);

// Frame `historyFrames` of an accumulation (`accumulate` > 0); frame 0 and every frame without
// accumulation get the settings' radii and `denoiseIterations`.
// - Every frame's density radius is at most kTravelRadiusFactor times the photon's travel:
//   light that came from a surface at distance d varies over about d (a wall's foot, a concave
//   corner), which a neighbour count blurs.
// - From frame 1 on, density discs hold kAveragedNeighbourShare of splat_neighbours, and radii
//   shrink as frames are averaged, as in progressive photon mapping (Knaus and Zwicker 2011):
//   frame i's squared radius is times prod_{j<i} (j + alpha) / (j + 1), about i^(alpha - 1), so
//   that the average's blur (bias ~ r^2) and noise (variance ~ 1 / (i r^2)) both go to zero;
//   strong photons count in their own density (spreadStrongPhotons off).
// - The average's noise variance falls as 1 / frames and each a-trous iteration widens the
//   filter 2x (4x its area): one iteration fewer for every 4x frames.
ProgressiveStep computeProgressiveStep(int accumulate, uint32_t historyFrames,
                                       int denoiseIterations);

// What the accumulated history holds: frames of the still view in it, whether it must start anew
// (a light, a setting or the scene changed) or be reprojected (the camera or an object moved),
// the camera and lights of its last frame, and the frames drawn since it started (the seed).
// AccumulatePass keeps it and moves it on with every frame it accumulates.
class AccumulationHistory {
  public:
    // A light, a setting or the scene changed: everything drawn before is stale.
    void restart();
    // The camera of the next frame; when it moved since the last frame, the still view starts
    // anew while the indirect light is reprojected. Returns whether it moved.
    bool setCamera(const Camera& camera);
    // Instances and lights were re-uploaded (GpuScene::updateDynamic): a light that changed
    // (`lightsVersion`, GpuScene::getLightsVersion) restarts the history; objects that moved only
    // end the still view (the direct light starts anew, the indirect is reprojected).
    void setSceneUpdated(uint64_t lightsVersion);
    // A frame seen through `clipFromWorld` with lights `lightsVersion` was accumulated.
    void addFrame(const glm::mat4& clipFromWorld, uint64_t lightsVersion);

    uint32_t getFrames() const { return mFrames; } // FrameInputs::historyFrames
    bool isReset() const { return mReset; }        // FrameInputs::historyReset
    bool isMoved() const { return mMoved; }        // FrameInputs::moved
    const glm::mat4& getPreviousClipFromWorld() const { return mPreviousClipFromWorld; }
    // FrameInputs::seed: per_frame moves on with every frame drawn, the others while
    // accumulating only (with each frame added since the last restart).
    uint32_t computeSeed(const FrameSettings& settings) const;

  private:
    uint32_t mFrames = 0;
    bool mReset = true;
    bool mMoved = false;
    glm::mat4 mPreviousClipFromWorld{1.0f};
    uint32_t mSequenceFrames = 0;
    uint64_t mLightsVersion = 0; // GpuScene::getLightsVersion of the history's lights
    Camera mCamera;              // the camera of the last frame
    uint32_t mFramesDrawn = 0;   // never restarted (rng per_frame)
};

class AccumulatePass final : public Pass {
  public:
    AccumulatePass(const GBuffer& viewer, const gl::Texture& direct, const gl::Texture& indirect);
    const char* getName() const override { return "accumulate"; }
    void resize(int width, int height) override;
    // Mixes the frame's light into the history and moves the history on (AccumulationHistory).
    void execute(const FrameInputs& inputs) override;
    // The history's bookkeeping, which the frame runner hands the passes (FrameInputs).
    const AccumulationHistory& getHistory() const { return mState; }
    // See AccumulationHistory: the runner says what changed, the history decides what it keeps.
    void restartHistory() { mState.restart(); }
    bool setCamera(const Camera& camera) { return mState.setCamera(camera); }
    void setSceneUpdated(uint64_t lightsVersion) { mState.setSceneUpdated(lightsVersion); }
    // Frames of the still view averaged into the light shown: at most `accumulate` (1 without
    // accumulation once a frame ran, 0 before). The indirect light may hold more
    // (getHistoryLength).
    uint32_t getAccumulatedFrames() const { return std::min(mState.getFrames(), mWindow); }
    void reloadPrograms(ShaderReloadReport& report) override { mProgram.reloadIfChanged(report); }
    const gl::Texture& getDirect() const { return mOutputs[kDirect]; }
    const gl::Texture& getIndirect() const { return mOutputs[kIndirect]; }
    // Frames each pixel's indirect light averages (R32F): 1 where its history started anew.
    const gl::Texture& getHistoryLength() const { return mOutputs[kLength]; }

  private:
    void mixIntoHistory(const FrameInputs& inputs);

    static constexpr size_t kDirect = 0;
    static constexpr size_t kIndirect = 1;
    static constexpr size_t kLength = 2;
    const GBuffer& mViewer;
    const gl::Texture& mDirect;
    const gl::Texture& mIndirect;
    ReloadableProgram mProgram;
    gl::Buffer mParams{"accumulate parameters", sizeof(gpu::AccumulateParams)};
    gl::VertexArray mVertexArray;
    std::array<gl::Texture, 3> mOutputs; // this frame's averages and lengths
    std::array<gl::Texture, 3> mHistory; // the last frame's
    gl::Texture mHistoryPosition;        // the last frame's viewer G-buffer position and normal
    gl::Texture mHistoryNormal;
    gl::Framebuffer mFramebuffer;
    AccumulationHistory mState;
    uint32_t mWindow = 1; // accumulate of the last frame, at least 1
};

} // namespace ispm
