// ImportancePass: each frame, where the viewer needs photons. A compute pass gathers samples of
// the viewer's G-buffer into a coarse map per light view (the texels that light what the viewer
// sees, directly and one bounce away); a second builds each map's sampling tables, mixed with a
// uniform floor of the light's power. The emit pass warps its grid through them.
#pragma once

#include "render/gbuffer.h"
#include "render/pass.h"

namespace ispm {

class ImportancePass final : public Pass {
public:
    ImportancePass(const GBuffer& viewer, const GBuffer& lights);
    const char* getName() const override { return "importance"; }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override {
        mGather.reloadIfChanged(report);
        mCdf.reloadIfChanged(report);
    }
    // Sampling tables (shared/importance_data.h) for the emit pass; gathered hits for views.
    const gl::Buffer& getCdf() const { return mCdfTables; }
    const gl::Buffer& getHits() const { return mHits; }
    size_t getGpuBytes() const { return mHits.getSize() + mCdfTables.getSize() + mParams.getSize(); }

private:
    const GBuffer& mViewer;
    const GBuffer& mLights;
    ReloadableProgram mGather;
    ReloadableProgram mCdf;
    gl::Buffer mParams;
    gl::Buffer mHits;
    gl::Buffer mCdfTables;
    size_t mViewCount = 0;
};

} // namespace ispm
