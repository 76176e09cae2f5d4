// The deferred passes after the G-buffers: direct light (shadow maps from the light views),
// compose (direct + indirect + emission, background) and tone mapping (with the white point
// derived on the GPU when luminance_max is not set).
#pragma once

#include "render/fullscreen.h"
#include "render/gbuffer.h"
#include "render/param_blocks.h"
#include "render/pass.h"

namespace ispm {

// Direct light at each pixel's centre (direct.frag), then, with edge_samples, averaged over the
// area of the pixels where it changes (edge_find.comp lists them, edge_shade.comp traces them).
class DirectPass final : public Pass {
  public:
    DirectPass(const GBuffer& viewer, const GBuffer& lights);
    const char* getName() const override { return "direct"; }
    void resize(int width, int height) override { mTarget.resize(width, height); }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override {
        mTarget.reloadProgram(report);
        mEdgeFind.reloadIfChanged(report);
        mEdgeShade.reloadIfChanged(report);
    }
    const gl::Texture& getOutput() const { return mTarget.getTexture(); }

  private:
    void shadeEdges(const FrameInputs& inputs);

    const GBuffer& mViewer;
    const GBuffer& mLights;
    FullscreenTarget mTarget;
    ParamBlocks<gpu::DirectParams> mParams;
    ProgramVariants mEdgeFind;  // by EDGE_EMISSION
    ProgramVariants mEdgeShade; // by SHADOW_RAYS and the scene's surface defines
    gl::Buffer mEdges;          // DirectEdgeHeader, then a uint per pixel; made at first use
    gl::Buffer mEdgeParams;     // DirectEdgeParams
};

class ComposePass final : public Pass {
  public:
    ComposePass(const GBuffer& viewer, const gl::Texture& direct, const gl::Texture& indirect);
    const char* getName() const override { return "compose"; }
    void resize(int width, int height) override { mTarget.resize(width, height); }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override { mTarget.reloadProgram(report); }
    const gl::Texture& getOutput() const { return mTarget.getTexture(); }

  private:
    const GBuffer& mViewer;
    const gl::Texture& mDirect;
    const gl::Texture& mIndirect;
    FullscreenTarget mTarget;
};

class TonemapPass final : public Pass {
  public:
    explicit TonemapPass(const gl::Texture& hdr);
    const char* getName() const override { return "tonemap"; }
    // The radiance it maps from the next frame on: the composed image, or the post passes'.
    void setInput(const gl::Texture& hdr) { mHdr = &hdr; }
    void resize(int width, int height) override { mTarget.resize(width, height); }
    void execute(const FrameInputs& inputs) override;
    const gl::Texture& getOutput() const { return mTarget.getTexture(); }
    // The white point used by the last frame (derived or set), read back: for reports only.
    float readLuminanceMax() const;
    void reloadPrograms(ShaderReloadReport& report) override {
        mHistogram.reloadIfChanged(report);
        mResolve.reloadIfChanged(report);
        mTarget.reloadProgram(report);
    }

  private:
    const gl::Texture* mHdr;
    ReloadableProgram mHistogram;
    ReloadableProgram mResolve;
    gl::Buffer mExposure;
    FullscreenTarget mTarget;
};

} // namespace ispm
