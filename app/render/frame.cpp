// FrameRunner: per-frame constants, pass order, timing.
#include "render/frame.h"
#include "render/accumulate_pass.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/debug.h"

#include <shared/gather_data.h>
#include <shared/photon_data.h>
#include <shared/scene_data.h>

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>

namespace ispm {
namespace {

// Whether a and b set every setting alike but the seed.
bool isSameButSeed(const Settings& a, const Settings& b) {
    const auto sameIn = [](const Settings& from, const Settings& other) {
        for (const auto& [name, value] : from.getOverrides()) {
            if (name != "seed" && other.get(name) != value) return false;
        }
        return true;
    };
    return sameIn(a, b) && sameIn(b, a);
}

} // namespace

double computeAdaptationWeight(double timeStepS, double timeConstantS) {
    if (timeConstantS <= 0.0 || timeStepS < 0.0) return 1.0;
    return 1.0 - std::exp(-timeStepS / timeConstantS);
}

Aov parseAov(const std::string& text, const std::string& where) {
    if (text == "direct") return Aov::Direct;
    if (text == "indirect") return Aov::Indirect;
    if (text == "total") return Aov::Total;
    throw InputError(strCat(where, ": expected direct, indirect or total, got '", text, "'"));
}

FrameRunner::FrameRunner(const Scene& scene, const Settings& settings, gl::TimingMethod timing)
    : mScene(scene), mSettings(settings), mFrameSettings(resolveFrameSettings(settings)),
      mWidth(mFrameSettings.width), mHeight(mFrameSettings.height),
      mBudget(int(findSetting("photons")->maxValue)), mTimer(timing),
      mGpuScene(scene, mFrameSettings.shadowMapSize),
      mFrameConstants("frame constants", sizeof(gpu::FrameConstants)) {
    mGBuffer = std::make_unique<GBufferPass>();
    mLightViews = std::make_unique<LightViewPass>();
    mImportance =
        std::make_unique<ImportancePass>(mGBuffer->getGBuffer(), mLightViews->getGBuffer());
    mEmit = std::make_unique<PhotonEmitPass>(mLightViews->getGBuffer(), mImportance->getCdf(),
                                             mPhotonBuffers);
    mTrace = std::make_unique<PhotonTracePass>(mPhotonBuffers);
    mDensity = std::make_unique<PhotonDensityPass>(mPhotonBuffers, mGBuffer->getGBuffer());
    mSplat = std::make_unique<SplatPass>(mGBuffer->getGBuffer(), mPhotonBuffers, *mDensity);
    mDenoise = std::make_unique<DenoisePass>(mGBuffer->getGBuffer(), mSplat->getOutput());
    mDirect = std::make_unique<DirectPass>(mGBuffer->getGBuffer(), mLightViews->getGBuffer());
    mUpsample = std::make_unique<UpsamplePass>(mGBuffer->getGBuffer(), mDenoise->getOutput(),
                                               mDenoise->getGuide(), mSplat->getCaustics());
    mAccumulate = std::make_unique<AccumulatePass>(mGBuffer->getGBuffer(), mDirect->getOutput(),
                                                   mUpsample->getOutput());
    mCompose = std::make_unique<ComposePass>(mGBuffer->getGBuffer(), mAccumulate->getDirect(),
                                             mAccumulate->getIndirect());
    mSpecular = std::make_unique<SpecularPass>(mGBuffer->getGBuffer(), mAccumulate->getIndirect(),
                                               mCompose->getOutput());
    mMotionBlur = std::make_unique<MotionBlurPass>(mGBuffer->getGBuffer());
    mDepthBlur = std::make_unique<DepthBlurPass>(mGBuffer->getGBuffer());
    mBloom = std::make_unique<BloomPass>();
    mTotal = &mCompose->getOutput();
    mTonemap = std::make_unique<TonemapPass>(*mTotal);
    mBudget.restart(mFrameSettings.photons);
    mTimings.method = mTimer.getMethod();
    resizePasses();
}

std::array<Pass*, 17> FrameRunner::listPasses() const {
    return {mGBuffer.get(),  mLightViews.get(), mImportance.get(), mEmit.get(),
            mDirect.get(),   mTrace.get(),      mDensity.get(),    mSplat.get(),
            mDenoise.get(),  mUpsample.get(),   mAccumulate.get(), mCompose.get(),
            mSpecular.get(), mMotionBlur.get(), mDepthBlur.get(),  mBloom.get(),
            mTonemap.get()};
}

void FrameRunner::resizePasses() {
    for (Pass* pass : listPasses())
        pass->resize(mWidth, mHeight);
}

ShaderReloadReport FrameRunner::reloadShaders() {
    ShaderReloadReport report;
    for (Pass* pass : listPasses())
        pass->reloadPrograms(report);
    return report;
}

void FrameRunner::setSettings(const Settings& settings) {
    if (isFrameInProgress()) {
        mPendingSettings = settings; // the frame in progress keeps its own
        return;
    }
    applySettings(settings);
}

void FrameRunner::applySettings(const Settings& settings) {
    mPendingSettings.reset();
    // A new seed alone (bench's timed frames, accumulation) keeps the importance maps'
    // history: any map is an unbiased pdf.
    if (isSameButSeed(mSettings, settings)) {
        mImportance->invalidateMaps();
    } else {
        mImportance->restartHistory();
    }
    // A budget starts from the photons set; other edits keep the one adapted so far.
    if (settings.get("photons") != mSettings.get("photons") ||
        settings.get("frame_ms_target") != mSettings.get("frame_ms_target")) {
        mBudget.restart(settings.getInt("photons"));
    }
    mBudget.dropMeasurements(); // measured at the old settings
    mSettings = settings;
    mFrameSettings = resolveFrameSettings(settings);
    mAccumulate->restartHistory();
    applyBudget();
    if (mFrameSettings.width != mWidth || mFrameSettings.height != mHeight) {
        mWidth = mFrameSettings.width;
        mHeight = mFrameSettings.height;
        resizePasses();
    }
}

void FrameRunner::updateFrameConstants() {
    // Accumulated frames look through new sub-pixel offsets: the average is anti-aliased.
    const glm::vec2 jitter = computeFrameJitter(mFrameSettings, getHistoryFrames());
    const uint32_t seed = mAccumulate->getHistory().computeSeed(mFrameSettings);
    gpu::FrameConstants fc =
        computeFrameConstants(mScene, mGpuScene, mFrameSettings, mWidth, mHeight, seed, jitter);
    mClipFromWorld = fc.clipFromWorld;
    fc.adaptationWeight =
        static_cast<float>(computeAdaptationWeight(mTimeStepS, mFrameSettings.eyeAdaptationS));
    mFrameConstants.upload(0, sizeof(fc), &fc);
}

void FrameRunner::runPass(Pass& pass, const FrameInputs& inputs) {
    gl::DebugGroup group(pass.getName());
    mTimer.begin(pass.getName());
    pass.execute(inputs);
    mTimer.end();
}

FrameInputs FrameRunner::getFrameInputs() const {
    const AccumulationHistory& history = mAccumulate->getHistory();
    return {mScene,
            mGpuScene,
            mFrameSettings,
            mFrameConstants,
            mClipFromWorld,
            mScene.camera.position,
            mWidth,
            mHeight,
            history.getFrames(),
            history.isReset(),
            history.isMoved(),
            history.getPreviousClipFromWorld(),
            history.computeSeed(mFrameSettings),
            computeProgressiveStep(mFrameSettings.accumulate, history.getFrames(),
                                   mFrameSettings.denoiseIterations),
            mSplatDraws};
}

void FrameRunner::setPresentation(const Presentation& presentation) {
    mTimeStepS = presentation.timeStepS;
    mGBuffer->setKeepMotion(presentation.keepVelocity);
}

FramePasses FrameRunner::getPasses() const {
    return {mScene,       mGpuScene,    mPhotonBuffers, *mGBuffer, *mLightViews,
            *mImportance, *mEmit,       *mTrace,        *mDensity, *mSplat,
            *mDenoise,    *mUpsample,   *mAccumulate,   *mDirect,  *mCompose,
            *mSpecular,   *mMotionBlur, *mDepthBlur,    *mBloom,   *mTonemap};
}

void FrameRunner::updateScene(SceneChange change) {
    if (change == SceneChange::AddedOrRemoved) {
        rebuildScene();
        return;
    }
    if (isFrameInProgress()) {
        mPendingSceneUpdate = true; // uploaded before the next frame
        return;
    }
    applySceneUpdate();
}

void FrameRunner::applySceneUpdate() {
    mPendingSceneUpdate = false;
    mGpuScene.updateDynamic(mScene);
    // Moved objects keep the importance maps (AccumulatePass reprojects; see ImportancePass).
    mAccumulate->setSceneUpdated(mGpuScene.getLightsVersion());
}

void FrameRunner::rebuildScene() {
    // Lights or instances were added or removed: the frame in progress has the old ones.
    dropFrameInProgress();
    mPendingSceneUpdate = false; // the new upload holds every edit
    mImportance->restartHistory();
    mGpuScene = GpuScene(mScene, mGpuScene.getLightResolution());
    mAccumulate->restartHistory();
}

void FrameRunner::dropFrameInProgress() {
    if (!isFrameInProgress()) return;
    // Steps up to the accumulation leave the history as it was; later ones only the display.
    mSteps.clear();
    mNextStep = 0;
    mTimer.discardFrame();
    if (mPendingSettings) applySettings(*mPendingSettings);
}

void FrameRunner::renderFrame() {
    beginFrame();
    continueFrame(kWholeFrameMs);
}

void FrameRunner::beginFrame(double sliceMs) {
    assert(!isFrameInProgress());
    if (mPendingSettings) applySettings(*mPendingSettings);
    if (mPendingSceneUpdate) applySceneUpdate();
    mSteps.clear();
    mNextStep = 0;
    if (mAccumulate->setCamera(mScene.camera)) mImportance->invalidateMaps();
    // A full history of a still view is the image: nothing changed, so nothing is drawn (a
    // resting camera costs nothing), and the image stands still.
    const auto window = static_cast<uint32_t>(mFrameSettings.accumulate);
    if (window > 0 && getHistoryFrames() >= window) {
        mTimings.passes.clear(); // no pass ran
        return;
    }
    mGpuScene.setViewer(mScene, mScene.camera, float(mWidth) / float(mHeight));
    // Accumulated frames also move the light cameras inside a texel: shadow edges anti-aliased.
    mGpuScene.setLightJitter(mFrameSettings.accumulate > 0 ? computeShadowJitter(getHistoryFrames())
                                                           : glm::vec2(0.0f));
    updateFrameConstants();
    const auto splatPasses = static_cast<uint32_t>(mFrameSettings.splatPasses);
    mSplatDraws = mFrameSettings.splatMode == gpu::kSplatModeGather
                      ? splatPasses
                      : chooseSlices(mSplat->getName(), sliceMs, splatPasses, gpu::kMaxSplatDraws);
    mInputs.emplace(getFrameInputs());
    addFrameSteps(sliceMs);
}

uint32_t FrameRunner::chooseSlices(const char* pass, double sliceMs, uint32_t fewest,
                                   uint32_t most) const {
    if (!std::isfinite(sliceMs)) return fewest;
    // Until the pass was timed, a sixteenth a slice: a first slow frame stalls the UI less.
    constexpr double kUntimedSlices = 16.0;
    // Each slice about half the UI frame's render time: the frame's other steps fit beside it.
    constexpr double kShareOfSlice = 0.5;
    const auto last = mLastPassMs.find(pass);
    const double wanted = last == mLastPassMs.end()
                              ? kUntimedSlices
                              : std::ceil(last->second / (kShareOfSlice * sliceMs));
    return static_cast<uint32_t>(std::clamp(wanted, double(fewest), double(most)));
}

void FrameRunner::addPassStep(Pass& pass) {
    mSteps.push_back({pass.getName(), [this, &pass] { runPass(pass, *mInputs); }});
}

void FrameRunner::addTimedStep(const char* costKey, const Pass& pass, std::function<void()> run) {
    // Timed and labelled as the pass: its slices add up to one row (setTimings).
    mSteps.push_back({costKey, [this, &pass, run = std::move(run)] {
                          gl::DebugGroup group(pass.getName());
                          mTimer.begin(pass.getName());
                          run();
                          mTimer.end();
                      }});
}

void FrameRunner::addFrameSteps(double sliceMs) {
    const FrameInputs& inputs = *mInputs;
    addPassStep(*mGBuffer);
    const size_t lightViews = LightViewPass::getViewCount(inputs);
    if (std::isfinite(sliceMs) && lightViews > 1) {
        for (size_t view = 0; view < lightViews; ++view) {
            addTimedStep("light view", *mLightViews,
                         [this, view] { mLightViews->executeViews(*mInputs, view, 1); });
        }
    } else {
        addPassStep(*mLightViews);
    }
    if (mFrameSettings.hasIndirect()) {
        addPassStep(*mImportance); // builds, blends or keeps its maps itself
        addPassStep(*mEmit);
    }
    addPassStep(*mDirect);
    if (mFrameSettings.hasIndirect()) {
        const uint32_t traceSlices =
            chooseSlices(mTrace->getName(), sliceMs, 1, gpu::kMaxComputeSlices);
        for (uint32_t slice = 0; slice < traceSlices; ++slice) {
            addTimedStep("trace slice", *mTrace, [this, slice, traceSlices] {
                mTrace->executeSlice(*mInputs, slice, traceSlices);
            });
        }
        const uint32_t stages = PhotonDensityPass::getStageCount(inputs.settings);
        const uint32_t densitySlices =
            chooseSlices(mDensity->getName(), sliceMs / stages, 1, gpu::kMaxComputeSlices);
        for (uint32_t stage = 0; stage < stages; ++stage) {
            for (uint32_t slice = 0; slice < densitySlices; ++slice) {
                addTimedStep("density slice", *mDensity, [this, stage, slice, densitySlices] {
                    mDensity->executeSlice(*mInputs, stage, slice, densitySlices);
                });
            }
        }
        if (inputs.settings.splatMode == gpu::kSplatModeGather) {
            addPassStep(*mSplat);
        } else {
            for (uint32_t draw = 0; draw < inputs.splatDraws; ++draw) {
                addTimedStep("splat draw", *mSplat,
                             [this, draw] { mSplat->executeDraws(*mInputs, draw, 1); });
            }
        }
    } else {
        // bounces = 0 or no photons: the image is direct light only.
        mSteps.push_back({"splat clear", [this] { mSplat->clear(*mInputs); }});
    }
    addPassStep(*mDenoise);
    addPassStep(*mUpsample);
    mSteps.push_back({mAccumulate->getName(), [this] {
                          runPass(*mAccumulate, *mInputs); // moves its history on
                          mGpuScene.keepTransformsAsPrevious();
                      }});
    addPassStep(*mCompose);
    // Off (specular_depth 0, or nothing in the scene to trace), the composed image is left
    // exactly as it was.
    if (SpecularPass::isOn(mFrameSettings, mGpuScene)) addPassStep(*mSpecular);
    mSteps.push_back({"post and tone map", [this] {
                          mTotal = &runPostPasses(*mInputs);
                          mTonemap->setInput(*mTotal);
                          runPass(*mTonemap, *mInputs);
                      }});
    mSteps.push_back({"timings", [this] { finishFrame(); }});
}

bool FrameRunner::continueFrame(double budgetMs) {
    using Clock = std::chrono::steady_clock;
    const auto msSince = [](Clock::time_point t) {
        return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
    };
    const Clock::time_point start = Clock::now();
    for (bool first = true; mNextStep < mSteps.size(); first = false) {
        const std::string key = mSteps[mNextStep].costKey;
        const auto cost = mStepCostMs.find(key);
        const double expectedMs = cost == mStepCostMs.end() ? 0.0 : cost->second;
        if (!first && msSince(start) + expectedMs > budgetMs) return false;
        const Clock::time_point stepStart = Clock::now();
        // Counted before it runs: the last step's settings change (finishFrame) applies at once.
        mSteps[mNextStep++].run();
        mStepCostMs[key] = msSince(stepStart);
    }
    mSteps.clear();
    mNextStep = 0;
    return true;
}

void FrameRunner::finishFrame() {
    if (auto samples = mTimer.collect()) {
        setTimings(*samples);
        adaptPhotonBudget();
    }
}

const gl::Texture& FrameRunner::runPostPasses(const FrameInputs& inputs) {
    // Camera effects on the scene's light first (the shutter, then the lens), then the bloom
    // that scatters the focused image.
    const gl::Texture* hdr = &mCompose->getOutput();
    if (mFrameSettings.hasMotionBlur()) {
        mMotionBlur->setInput(*hdr);
        runPass(*mMotionBlur, inputs);
        hdr = &mMotionBlur->getOutput();
    }
    if (mFrameSettings.hasDepthBlur()) {
        mDepthBlur->setInput(*hdr);
        runPass(*mDepthBlur, inputs);
        hdr = &mDepthBlur->getOutput();
    }
    if (mFrameSettings.hasBloom()) {
        mBloom->setInput(*hdr);
        runPass(*mBloom, inputs);
        hdr = &mBloom->getOutput();
    }
    return *hdr;
}

void FrameRunner::adaptPhotonBudget() {
    // A still view that accumulates is converging (once its history is full, frames cost
    // nothing).
    const bool converging = mFrameSettings.accumulate > 0 && getHistoryFrames() > 1;
    // The passes whose work follows the photon count.
    const std::vector<std::string> photonPasses = {mEmit->getName(), mTrace->getName(),
                                                   mDensity->getName(), mSplat->getName()};
    if (!mBudget.recordFrame(splitFrameCost(mTimings.passes, photonPasses),
                             mFrameSettings.frameMsTarget, converging,
                             uint32_t(mTimer.getFramesInFlight()))) {
        return;
    }
    // Only the photon count changes: the accumulated and importance histories stay (any count
    // estimates the same light), and a moving view keeps its reprojected light.
    applyBudget();
}

void FrameRunner::applyBudget() {
    ispm::applyPhotonBudget(mFrameSettings, mSettings, mBudget.getPhotons());
    // The light G-buffer follows the light views' resolution on its next execute.
    mGpuScene.setLightResolution(mScene, mFrameSettings.shadowMapSize);
}

void FrameRunner::waitForTimings() {
    // bench and render wait after every frame, so finishFrame's collect rarely finds a frame's
    // queries answered on a GPU: the budget follows these.
    if (auto samples = mTimer.collectLatest()) {
        setTimings(*samples);
        adaptPhotonBudget();
    }
}

void FrameRunner::setTimings(const std::vector<gl::PassTimer::Sample>& samples) {
    // A pass drawn in several slices (the splat's draws) is one row: their sum.
    std::vector<PassTiming>& passes = mTimings.passes;
    passes.clear();
    for (const gl::PassTimer::Sample& s : samples) {
        auto same = std::find_if(passes.begin(), passes.end(),
                                 [&](const PassTiming& t) { return t.name == s.name; });
        if (same == passes.end()) {
            passes.push_back({s.name, s.ms});
        } else {
            same->ms += s.ms;
        }
    }
    for (const PassTiming& t : passes)
        mLastPassMs[t.name] = t.ms;
}

PhotonCounts readPhotonCounts(const FrameRunner& runner) {
    if (!runner.getFrameSettings().hasIndirect()) return {};
    const FramePasses passes = runner.getPasses();
    return passes.photons.readCounts(passes.emit.getEmittedPerLight());
}

const gl::Texture& FrameRunner::getAov(Aov aov) const {
    switch (aov) {
    case Aov::Direct:
        return mAccumulate->getDirect();
    case Aov::Indirect:
        return mAccumulate->getIndirect();
    case Aov::Total:
        return *mTotal;
    case Aov::Display:
        return mTonemap->getOutput();
    }
    return mCompose->getOutput();
}

size_t computeGpuBytes(const FrameRunner& runner) {
    constexpr size_t kBytesRgba32F = 16;
    constexpr size_t kBytesRgba8 = 4;
    // direct, indirect, total, and both lights' average and history
    constexpr size_t kFullResolutionRgba32F = 7;
    // Splat buffer and the filter's two targets, at splat_resolution.
    constexpr size_t kSplatResolutionRgba32F = 3;
    const FrameSettings& settings = runner.getFrameSettings();
    const FramePasses p = runner.getPasses();
    const glm::ivec2 splat = settings.splatSize;
    const size_t pixels =
        static_cast<size_t>(settings.width) * static_cast<size_t>(settings.height);
    return p.scene.getGpuBytes() + p.photons.getGpuBytes() + p.importance.getGpuBytes() +
           p.density.getGpuBytes() + p.splat.getGpuBytes() + p.gbuffer.getGBuffer().getGpuBytes() +
           p.lightViews.getGBuffer().getGpuBytes() + p.motionBlur.getGpuBytes() +
           p.depthBlur.getGpuBytes() + p.bloom.getGpuBytes() +
           pixels * (kFullResolutionRgba32F * kBytesRgba32F + kBytesRgba8) +
           size_t(splat.x) * size_t(splat.y) * kSplatResolutionRgba32F * kBytesRgba32F;
}

} // namespace ispm
