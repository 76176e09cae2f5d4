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
    void execute(const FrameInputs& inputs) override;
    // Keep last frame's maps instead of building new ones (FrameRunner: nothing they depend on
    // changed); the next execute does nothing.
    void setKeepMaps(bool keep) { mKeepMaps = keep; }
    // Blend this frame's samples into the maps of earlier frames (importance_frames), gathering
    // importance_samples / importance_frames of them; else build the maps from all of them anew
    // (FrameRunner: settings, size, scene or an emitting light view changed since).
    void setKeepHistory(bool keep) { mKeepHistory = keep; }
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
    bool mKeepMaps = false;
    bool mKeepHistory = false;
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
