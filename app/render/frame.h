// The frame runner: wires the passes in data-flow order (docs/design.md "Frame, as data flows"),
// wraps each in a debug group and a timer named after it, and exposes the AOVs.
#pragma once

#include "gl/timer.h"
#include "render/accumulate_pass.h"
#include "render/denoise_pass.h"
#include "render/frame_budget.h"
#include "render/frame_constants.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "render/importance_pass.h"
#include "render/photon_density_pass.h"
#include "render/photon_emit_pass.h"
#include "render/photon_trace_pass.h"
#include "render/post_pass.h"
#include "render/shading_passes.h"
#include "render/specular_pass.h"
#include "render/splat_pass.h"
#include "render/upsample_pass.h"
#include "scene/scene.h"

#include <shared/scene_data.h>

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace ispm {

enum class Aov { Direct, Indirect, Total, Display };

// Eye adaptation: the share of the way from the last frame's white point to this frame's after
// `timeStepS` (< 0: unknown, at once) with time constant `timeConstantS` (0: at once).
double computeAdaptationWeight(double timeStepS, double timeConstantS);

// Parses "direct|indirect|total"; throws InputError naming `where` otherwise.
Aov parseAov(const std::string& text, const std::string& where);

class FrameRunner {
  public:
    // `settings` are the effective settings (scene overrides with the command line on top).
    FrameRunner(const Scene& scene, const Settings& settings, gl::TimingMethod timing);

    // A whole frame, at once (render, bench, tests).
    void renderFrame();
    // A frame in slices (the viewer: its UI keeps its own rate whatever a frame costs).
    // beginFrame() takes the camera, the scene and the settings as they are and lists the frame's
    // steps: a pass each, the trace, density and raster splat passes in slices of about half
    // `sliceMs` each (from their last timed frame; at most kMaxComputeSlices, kMaxSplatDraws).
    // continueFrame(budgetMs) runs steps until the next would pass `budgetMs` by the time it took
    // last (at least one step) and says whether the frame is done. While a frame is in progress,
    // setSettings and updateScene wait for the next beginFrame (getSettings says what comes);
    // rebuildScene drops it. The images are those of renderFrame() up to the order in which photons
    // are stored and added (float rounding).
    static constexpr double kWholeFrameMs = std::numeric_limits<double>::infinity();
    void beginFrame(double sliceMs = kWholeFrameMs);
    bool continueFrame(double budgetMs);
    bool isFrameInProgress() const { return mNextStep < mSteps.size(); }
    // Seconds since the previous frame, for eye adaptation (eye_adaptation_s); until set, every
    // frame adapts at once (a still render).
    void setTimeStep(double seconds) { mTimeStepS = seconds; }
    // Viewer edits (both cheap when nothing relevant changed). setSettings resizes the passes when
    // width/height change and re-uploads the scene when shadow_map_size changes; every other
    // setting is read by the passes each frame. updateScene re-uploads instance transforms and
    // lights after the caller edited the Scene this runner was built on; rebuildScene uploads it
    // anew (BVH included) when lights or instances were added or removed.
    void setSettings(const Settings& settings);
    // Frames of the still view averaged into the light shown: at most `accumulate` (1 without
    // accumulation, once a frame ran). The indirect light may hold more (getHistoryLength).
    uint32_t getAccumulatedFrames() const { return mAccumulate->getAccumulatedFrames(); }
    // Frames each pixel's indirect light averages (R32F), with `accumulate` > 0.
    const gl::Texture& getHistoryLength() const { return mAccumulate->getHistoryLength(); }
    // setSettings and rebuildScene restart the accumulated history (`accumulate`), as does
    // updateScene when a light changed; when only objects moved, and when the camera moved, the
    // indirect history is reprojected and the direct light's restarts.
    void updateScene();
    void rebuildScene();
    // The settings of the next frame (those set while a frame was in progress included).
    const Settings& getSettings() const { return mPendingSettings ? *mPendingSettings : mSettings; }
    const FrameSettings& getFrameSettings() const { return mFrameSettings; }
    const Scene& getScene() const { return mScene; }
    // F5: rebuilds the passes' programs whose source files changed; failures keep the old ones.
    ShaderReloadReport reloadShaders();
    // Pass times of the newest frame whose timer results are in, read without waiting: with
    // timer queries (a GPU) a frame or a few behind the last renderFrame(); with the CPU clock
    // (llvmpipe) the last frame's. waitForTimings() waits for the last frame's (bench, render).
    const std::vector<PassTiming>& getLastTimings() const { return mTimings; }
    void waitForTimings();
    gl::TimingMethod getTimingMethod() const { return mTimer.getMethod(); }

    // Linear radiance (Direct, Indirect, Total) or display values (Display), row 0 at the bottom.
    // Total is after the post passes (motion blur, depth blur, bloom) when any is on; Direct and
    // Indirect are the lights as composed, never post-processed.
    const gl::Texture& getAov(Aov aov) const;
    // The last frame's own direct or indirect light, before accumulation (tests, debug views).
    const gl::Texture& getFrameLight(Aov aov) const;
    // Whether the photon passes run (bounces > 0 and photons > 0).
    bool hasIndirect() const;
    // Photon counts of the last frame, read back from the GPU (for reports; waits for the GPU).
    PhotonCounts readPhotonCounts() const;
    const PhotonBuffers& getPhotonBuffers() const { return mPhotonBuffers; }
    // The emission grids of the last frame (light view, size, first photon index).
    const std::vector<EmissionGrid>& getEmissionGrids() const { return mEmit->getGrids(); }
    const GpuScene& getGpuScene() const { return mGpuScene; }
    // What the passes were given in the last frame (valid after renderFrame), so a pass can be
    // run on its own against the same frame: tests and debug views.
    FrameInputs getFrameInputs() const;
    const GBuffer& getViewerGBuffer() const { return mGBuffer->getGBuffer(); }
    // The viewer G-buffer's velocity channel is drawn with motion blur on, or when kept (the
    // viewer's debug view showing it); otherwise it holds zero.
    void setKeepVelocity(bool keep) { mGBuffer->setKeepMotion(keep); }
    const GBuffer& getLightGBuffer() const { return mLightViews->getGBuffer(); }
    const ImportancePass& getImportance() const { return *mImportance; }
    float readLuminanceMax() const { return mTonemap->readLuminanceMax(); }
    int getWidth() const { return mWidth; }
    int getHeight() const { return mHeight; }
    size_t getGpuBytes() const;

  private:
    // One step of a frame in progress; `costKey` names its measured time (mStepCostMs).
    struct FrameStep {
        std::string costKey;
        std::function<void()> run;
    };
    void addPassStep(Pass& pass);
    // A step that runs a share of `pass` (a slice), timed under the pass's name.
    void addTimedStep(const char* costKey, const Pass& pass, std::function<void()> run);
    void addFrameSteps(double sliceMs);
    void finishFrame();         // the frame's timings, the adapted photon budget
    void dropFrameInProgress(); // rebuildScene while a frame is in progress
    void applySettings(const Settings& settings);
    void applySceneUpdate();
    // Slices of `pass` so each takes about half of `sliceMs` (from its last timed frame), in
    // [fewest, most]; `fewest` for a whole frame at once.
    uint32_t chooseSlices(const char* pass, double sliceMs, uint32_t fewest, uint32_t most) const;
    void resizePasses();
    void updateFrameConstants();
    // The still view's frames so far (AccumulatePass's history).
    uint32_t getHistoryFrames() const { return mAccumulate->getHistory().getFrames(); }
    // Every pass in frame order, for resize and shader reload.
    std::array<Pass*, 17> getPasses() const;
    void runPass(Pass& pass, const FrameInputs& inputs);
    // The post passes that are on, chained from the composed image; returns their output (the
    // composed image when none is on).
    const gl::Texture& runPostPasses(const FrameInputs& inputs);

    const Scene& mScene;
    Settings mSettings;
    FrameSettings mFrameSettings; // mSettings resolved
    double mTimeStepS = -1.0;     // setTimeStep; < 0: not set
    int mWidth;
    int mHeight;
    void setTimings(const std::vector<gl::PassTimer::Sample>& samples);
    // frame_ms_target: hands the newest timings to the budget and applies a new one.
    void adaptPhotonBudget();
    // The budget's photons over the settings as resolved, and the light views' resolution that
    // may follow them (shadows ray): the light views are re-made, the BVH stays.
    void applyBudget();

    // The frame in progress (beginFrame/continueFrame): its steps, the next one, its inputs.
    std::vector<FrameStep> mSteps;
    size_t mNextStep = 0;
    std::optional<FrameInputs> mInputs;
    uint32_t mSplatDraws = 1;                            // FrameInputs::splatDraws
    std::optional<Settings> mPendingSettings;            // set while a frame was in progress
    bool mPendingSceneUpdate = false;                    // likewise, updateScene
    std::unordered_map<std::string, double> mStepCostMs; // each step's time when it last ran
    std::unordered_map<std::string, double> mLastPassMs; // each pass's time, last timed frame

    FrameBudget mBudget; // frame_ms_target's photons (mFrameSettings.photons)
    gl::PassTimer mTimer;
    std::vector<PassTiming> mTimings;
    GpuScene mGpuScene;
    gl::Buffer mFrameConstants;
    glm::mat4 mClipFromWorld{1.0f};
    std::unique_ptr<GBufferPass> mGBuffer;
    std::unique_ptr<LightViewPass> mLightViews;
    std::unique_ptr<ImportancePass> mImportance;
    PhotonBuffers mPhotonBuffers;
    std::unique_ptr<PhotonEmitPass> mEmit;
    std::unique_ptr<PhotonTracePass> mTrace;
    std::unique_ptr<PhotonDensityPass> mDensity;
    std::unique_ptr<SplatPass> mSplat;
    std::unique_ptr<DenoisePass> mDenoise;
    std::unique_ptr<UpsamplePass> mUpsample;
    std::unique_ptr<AccumulatePass> mAccumulate;
    std::unique_ptr<DirectPass> mDirect;
    std::unique_ptr<ComposePass> mCompose;
    std::unique_ptr<SpecularPass> mSpecular; // adds mirror and glass rays into compose's image
    std::unique_ptr<MotionBlurPass> mMotionBlur;
    std::unique_ptr<DepthBlurPass> mDepthBlur;
    std::unique_ptr<BloomPass> mBloom;
    const gl::Texture* mTotal = nullptr; // the last frame's total: compose's or the post passes'
    std::unique_ptr<TonemapPass> mTonemap;
};

} // namespace ispm
