// ImportancePass: each frame, where the viewer needs photons. A compute pass gathers samples of
// the viewer's G-buffer into a coarse map per light view (the texels that light what the viewer
// sees, directly and one bounce away); a second blends them into the maps of earlier frames
// (importance_frames: an exponential average, so a frame gathers a share of the samples) and
// builds each map's sampling tables, mixed with a uniform floor of the light's power. The emit
// pass warps its grid through them.
#pragma once

#include "render/gbuffer.h"
#include "render/pass.h"

#include <shared/importance_data.h>

namespace ispm {

class ImportancePass final : public Pass {
  public:
    ImportancePass(const GBuffer& viewer, const GBuffer& lights);
    const char* getName() const override { return "importance"; }
    // A new size voids the maps and their history (restartHistory).
    void resize(int width, int height) override;
    // Builds the maps, or keeps last frame's when nothing they depend on changed since (the
    // view, the seed, a light view, a setting): any map is an unbiased pdf, and a kept one keeps
    // the photons' first hits (and with rng fixed or object_space their paths) where nothing
    // moved; objects that moved alone keep them. A new build blends this frame's samples into
    // the maps of earlier frames (importance_frames), gathering importance_samples /
    // importance_frames of them, unless their history is void (restartHistory, or an emitting
    // light view moved); a moved camera keeps it: its aim lags a few frames.
    void execute(const FrameInputs& inputs) override;
    // The camera moved or the seed alone changed: the next execute builds new maps, blended into
    // the history.
    void invalidateMaps() { mStale = true; }
    // Settings or the scene changed: the next execute builds the maps from its own samples alone.
    void restartHistory() {
        mStale = true;
        mFresh = true;
    }
    void reloadPrograms(ShaderReloadReport& report) override {
        mGather.reloadIfChanged(report);
        mCdf.reloadIfChanged(report);
    }
    // Sampling tables (shared/importance_data.h) for the emit pass.
    const gl::Buffer& getCdf() const { return mCdfTables; }
    // The emission pdf of every map texel relative to a uniform map (RGBA32F array, a layer per
    // light view): the viewer's "light importance" view.
    const gl::Texture& getPdfMap() const { return mPdfMap; }
    size_t getGpuBytes() const {
        constexpr size_t kBytesRgba32F = 16;
        return mHits.getSize() + mHistory.getSize() + mCdfTables.getSize() +
               mFilteredRows.getSize() + mParams.getSize() +
               mViewCount * gpu::kImportanceTexels * kBytesRgba32F;
    }

  private:
    void buildMaps(const FrameInputs& inputs, bool keepMaps, bool keepHistory);

    // What the maps were last built for: stale after a camera move, a settings change or a
    // rebuilt scene; else rebuilt when the seed or a light view changed.
    bool mStale = true;
    // The maps' history is void: settings, size or scene changed since the last build; also void
    // when GpuScene::getEmittingViewsVersion moved from mEmittingViews.
    bool mFresh = true;
    uint64_t mEmittingViews = 0;
    uint32_t mSeed = 0;
    uint64_t mLightViews = 0;
    uint32_t mBlends = 0; // frames blended into the history since it was built anew
    const GBuffer& mViewer;
    const GBuffer& mLights;
    ProgramVariants mGather; // by SHADOW_RAYS (setting shadows)
    ReloadableProgram mCdf;
    gl::Buffer mParams;
    gl::Buffer mHits;
    gl::Buffer mHistory; // per view and texel: the maps' importance per sample, averaged (float)
    gl::Buffer mCdfTables;
    gl::Buffer mFilteredRows; // the CDF build's scratch (kBindingImportanceRows)
    gl::Texture mPdfMap;
    size_t mViewCount = 0;
};

} // namespace ispm
