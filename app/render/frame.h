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

// Pass times of one frame (getTimings), and how they were measured.
struct FrameTimings {
    std::vector<PassTiming> passes; // in frame order; a pass drawn in slices is one row
    gl::TimingMethod method = gl::TimingMethod::CpuFinish;
};

// The runner's passes and the resources they share, read-only (getPasses): their outputs for
// debug views, reports and tests that run a pass on its own. Each pass owns its state.
struct FramePasses {
    const Scene& model; // the Scene the runner was built on
    const GpuScene& scene;
    const PhotonBuffers& photons;
    const GBufferPass& gbuffer;       // the viewer G-buffer
    const LightViewPass& lightViews;  // the light G-buffer
    const ImportancePass& importance; // its pdf map: the viewer's "light importance" view
    const PhotonEmitPass& emit;       // its emission grids
    const PhotonTracePass& trace;
    const PhotonDensityPass& density;
    const SplatPass& splat;
    const DenoisePass& denoise;
    const UpsamplePass& upsample;     // the last frame's own indirect light, at full resolution
    const AccumulatePass& accumulate; // the history: its frames and per-pixel lengths
    const DirectPass& direct;         // the last frame's own direct light
    const ComposePass& compose;
    const SpecularPass& specular;
    const MotionBlurPass& motionBlur;
    const DepthBlurPass& depthBlur;
    const BloomPass& bloom;
    const TonemapPass& tonemap; // the display image and its white point
};

// What the caller knows of how frames are shown, kept until set again (setPresentation).
struct Presentation {
    // Seconds since the previous frame, for eye adaptation (eye_adaptation_s); < 0: unknown,
    // the frame adapts at once (a still render).
    double timeStepS = -1.0;
    // The viewer G-buffer's velocity channel is drawn with motion blur on, or when kept (the
    // viewer's debug view showing it); otherwise it holds zero.
    bool keepVelocity = false;
};

// What the caller changed in the Scene the runner was built on (updateScene).
enum class SceneChange {
    Edited,         // instance transforms or lights moved or changed: re-uploaded
    AddedOrRemoved, // lights or instances added or removed: uploaded anew, BVH included
};

// Orders the passes, hands them typed inputs, and wraps each in a debug group and a timer. The
// passes keep their own state (AccumulatePass its history, ImportancePass its maps' history);
// the runner keeps the frame's: settings, the frame budget, the steps of a sliced frame.
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
    // setSettings and updateScene(Edited) wait for the next beginFrame (getSettings says what
    // comes); updateScene(AddedOrRemoved) drops it. The images are those of renderFrame() up to
    // the order in which photons are stored and added (float rounding).
    static constexpr double kWholeFrameMs = std::numeric_limits<double>::infinity();
    void beginFrame(double sliceMs = kWholeFrameMs);
    bool continueFrame(double budgetMs);
    bool isFrameInProgress() const { return mNextStep < mSteps.size(); }

    // Viewer edits (cheap when nothing relevant changed). setSettings resizes the passes when
    // width/height change and re-makes the light views when shadow_map_size changes; every other
    // setting is read by the passes each frame. It restarts the accumulated history, as does
    // updateScene when a light changed or was added or removed; when only objects moved, and
    // when the camera moved, the indirect history is reprojected and the direct light's restarts.
    void setSettings(const Settings& settings);
    void updateScene(SceneChange change = SceneChange::Edited);
    void setPresentation(const Presentation& presentation);
    // F5: rebuilds the passes' programs whose source files changed; failures keep the old ones.
    ShaderReloadReport reloadShaders();
    // Waits for the last frame's pass times (bench, render); see getTimings.
    void waitForTimings();

    // The settings of the next frame as set (those set while a frame was in progress included).
    const Settings& getSettings() const { return mPendingSettings ? *mPendingSettings : mSettings; }
    // The settings resolved as the passes read them (the frame in progress keeps its own): with
    // frame_ms_target, `photons` and what derives from it are the adapted budget's.
    const FrameSettings& getFrameSettings() const { return mFrameSettings; }
    // Pass times of the newest frame whose timer results are in, read without waiting: with
    // timer queries (a GPU) a frame or a few behind the last renderFrame(); with the CPU clock
    // (llvmpipe) the last frame's.
    const FrameTimings& getTimings() const { return mTimings; }
    // Linear radiance (Direct, Indirect, Total) or display values (Display), row 0 at the bottom.
    // Total is after the post passes (motion blur, depth blur, bloom) when any is on; Direct and
    // Indirect are the lights as composed, never post-processed.
    const gl::Texture& getAov(Aov aov) const;
    // The passes and what they share, read-only (FramePasses).
    FramePasses getPasses() const;
    // What the passes were given in the last frame (valid after renderFrame), so a pass can be
    // run on its own against the same frame: tests and debug views.
    FrameInputs getFrameInputs() const;

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
    void dropFrameInProgress(); // AddedOrRemoved while a frame is in progress
    void applySettings(const Settings& settings);
    void rebuildScene();
    void applySceneUpdate();
    // Slices of `pass` so each takes about half of `sliceMs` (from its last timed frame), in
    // [fewest, most]; `fewest` for a whole frame at once.
    uint32_t chooseSlices(const char* pass, double sliceMs, uint32_t fewest, uint32_t most) const;
    void resizePasses();
    void updateFrameConstants();
    // The still view's frames so far (AccumulatePass's history).
    uint32_t getHistoryFrames() const { return mAccumulate->getHistory().getFrames(); }
    // Every pass in frame order, for resize and shader reload.
    std::array<Pass*, 17> listPasses() const;
    void runPass(Pass& pass, const FrameInputs& inputs);
    // The post passes that are on, chained from the composed image; returns their output (the
    // composed image when none is on).
    const gl::Texture& runPostPasses(const FrameInputs& inputs);

    const Scene& mScene;
    Settings mSettings;
    FrameSettings mFrameSettings; // mSettings resolved
    double mTimeStepS = -1.0;     // Presentation::timeStepS
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
    FrameTimings mTimings;
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

// Photon counts of the last frame, read back from the GPU (for reports; waits for the GPU).
PhotonCounts readPhotonCounts(const FrameRunner& runner);
// GPU memory the runner's scene, buffers and targets hold (bench's report).
size_t computeGpuBytes(const FrameRunner& runner);

} // namespace ispm
