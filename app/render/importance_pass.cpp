// Importance: gather (viewer samples -> per-view hit maps), then tables (maps -> CDFs).
#include "render/importance_pass.h"

#include "gl/state.h"
#include "render/gpu_scene.h"
#include "settings/settings.h"

#include <shared/importance_data.h>
#include <shared/scene_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// A visible point lit directly matters less than one a bounce away: the photon that lands on it
// shows only after a further bounce, while a photon landing one bounce away lights it directly.
constexpr float kVisibleWeight = 0.5f;
constexpr float kBounceWeight = 1.0f;
// A visible point that no light reaches is lit by bounced light alone, much of it after two
// bounces (a room lit through its door: the yard's walls light the yard that lights the room), so
// its gather goes a bounce further. Photons from a part of the light's view the maps miss carry
// up to 1 / (1 - importance) times the power of an unaimed one, and the few that reach such a
// point by two bounces splat a blotch: courtyard room at the defaults, seeds 1-40, relMSE mean
// 0.0310 -> 0.0271, 90th percentile 0.0485 -> 0.0342 (the floor's frames from up to 1.62 of the
// reference's indirect light to 1.16 at the 90th percentile); courtyard outside 0.00389 ->
// 0.00376; Cornell box the same. From every visible point (lit ones too) it spread the maps over
// distant surfaces instead: outside 0.00340 -> 0.00365 (seeds 1-24).
constexpr float kUnlitSecondBounceWeight = 0.5f;
// Gather seed step between blended frames (2^32 / golden ratio: successive seeds spread apart).
constexpr uint32_t kBlendSeedStep = 0x9e3779b9u;

size_t computeCdfFloats(size_t views) {
    return views * (gpu::kImportanceTexels + gpu::kImportanceSize);
}

} // namespace

ImportancePass::ImportancePass(const GBuffer& viewer, const GBuffer& lights)
    : mViewer(viewer), mLights(lights),
      mGather({.label = "importance gather",
               .stages = {{gl::ShaderStage::Compute, "importance/importance_gather.comp"}},
               .defines = getGBufferDefines()}),
      mCdf(ReloadableProgram(
          {.label = "importance tables",
           .stages = {{gl::ShaderStage::Compute, "importance/importance_cdf.comp"}},
           .defines = getGBufferDefines()})),
      mParams("importance parameters", sizeof(gpu::ImportanceParams)) {}

void ImportancePass::resize(int width, int height) {
    (void)width;
    (void)height;
    restartHistory();
}

void ImportancePass::execute(const FrameInputs& inputs) {
    const GpuScene& scene = inputs.scene;
    const bool sameAim =
        !mStale && inputs.seed == mSeed && scene.getLightViewsVersion() == mLightViews;
    const bool keepHistory = !mFresh && scene.getEmittingViewsVersion() == mEmittingViews;
    buildMaps(inputs, sameAim, keepHistory); // its timer row reads ~0 ms when kept
    mStale = false;
    mFresh = false;
    mSeed = inputs.seed;
    mLightViews = scene.getLightViewsVersion();
    mEmittingViews = scene.getEmittingViewsVersion();
}

void ImportancePass::buildMaps(const FrameInputs& inputs, bool keepMaps, bool keepHistory) {
    const std::vector<LightCamera>& cameras = inputs.scene.getLightCameras();
    const size_t views = cameras.size();
    if (views == 0) return;
    if (keepMaps && views == mViewCount) return;
    if (views != mViewCount) {
        mHits = gl::Buffer("importance hits", views * gpu::kImportanceTexels * sizeof(uint32_t));
        mHistory = gl::Buffer("importance history", views * gpu::kImportanceTexels * sizeof(float));
        keepHistory = false; // nothing in it yet
        mCdfTables = gl::Buffer("importance tables", computeCdfFloats(views) * sizeof(float));
        mFilteredRows = gl::Buffer("importance filtered rows",
                                   views * gpu::kImportanceTexels * 2 * sizeof(float));
        mPdfMap = gl::Texture::create2DArray("importance pdf", gl::Format::RGBA32F,
                                             int(gpu::kImportanceSize), int(gpu::kImportanceSize),
                                             int(views));
        // A shadow-only view's layer is never written (no tables): the viewer shows it black.
        mPdfMap.clear(glm::vec4(0.0f));
        mViewCount = views;
    }
    // Gather samples on a grid of the image's aspect, at most one per pixel: all of
    // importance_samples on a first frame, 1 / importance_frames of them when blended into the
    // maps' history with that weight.
    const int frames = inputs.settings.importanceFrames;
    const bool blend = keepHistory && frames > 1;
    const double samples = std::max(inputs.settings.importanceSamples / (blend ? frames : 1), 1);
    const double aspect = double(inputs.width) / double(inputs.height);
    const auto across =
        uint32_t(std::clamp(std::lround(std::sqrt(samples * aspect)), 1L, long(inputs.width)));
    const auto down = uint32_t(std::clamp(std::lround(samples / across), 1L, long(inputs.height)));
    // Without gather samples nothing is aimed (FrameSettings: share 0): the tables follow the
    // light's power alone.
    const float share = inputs.settings.importance;
    gpu::ImportanceParams params{};
    // Blended frames jitter their samples anew even where the seed stays (rng fixed: a moving
    // view), so that the average covers the pixels; a first frame draws with the seed alone.
    mBlends = blend ? mBlends + 1 : 0;
    const uint32_t gatherSeed = inputs.seed + mBlends * kBlendSeedStep;
    params.gatherSamples = glm::uvec2(across, down);
    params.lightViewCount = uint32_t(views);
    params.seed = gatherSeed;
    params.importanceShare = share;
    params.visibleWeight = kVisibleWeight;
    params.bounceWeight = kBounceWeight;
    params.rayOffsetM = inputs.scene.getRayEpsilon();
    params.historyWeight = blend ? 1.0f / float(frames) : 1.0f;
    params.hitScale = 1.0f / (gpu::kImportanceFixedPoint * float(across * down));
    params.unlitWeight = kUnlitSecondBounceWeight;
    mParams.upload(0, sizeof(params), &params);

    inputs.scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingImportanceParams);
    mHits.bindBase(gl::BufferTarget::Storage, gpu::kBindingImportanceHits);
    mCdfTables.bindBase(gl::BufferTarget::Storage, gpu::kBindingImportanceCdf);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mLights.bindTextures(gpu::kUnitLightGBufferFirst);
    if (share > 0.0f) {
        mHits.clearToZero();
        std::vector<std::string> defines = inputs.scene.getRayDefines();
        defines.push_back(getShadowRaysDefine(inputs.settings));
        mGather.get(defines).use();
        const uint32_t count = across * down;
        gl::dispatchCompute((count + gpu::kImportanceGroupSize - 1) / gpu::kImportanceGroupSize);
        gl::memoryBarrier(gl::Barrier::Storage);
    }
    mCdf.use();
    mHistory.bindBase(gl::BufferTarget::Storage, gpu::kBindingImportanceHistory);
    mFilteredRows.bindBase(gl::BufferTarget::Storage, gpu::kBindingImportanceRows);
    mPdfMap.bindImage(gpu::kImageImportancePdf, false, true);
    // Shadow-only views (after the others) emit no photons: no tables.
    const auto emitting = static_cast<uint32_t>(std::count_if(
        cameras.begin(), cameras.end(), [](const LightCamera& c) { return !c.isShadowOnly; }));
    gl::dispatchCompute(emitting);
    // The emit pass's geometry stage reads the tables; the viewer samples the pdf map.
    gl::memoryBarrier(gl::Barrier::Storage | gl::Barrier::TextureFetch);
}

} // namespace ispm
