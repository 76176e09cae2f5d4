// DenoisePass: the splats' indirect light through `denoise` iterations of an edge-aware a-trous
// filter (steps 1, 2, 4, ... pixels of the splat buffer) guided by the viewer G-buffer; 0 passes
// it through. It works at the splat buffer's resolution; UpsamplePass follows.
#pragma once

#include "render/fullscreen.h"
#include "render/gbuffer.h"
#include "render/param_blocks.h"
#include "render/pass.h"

#include <array>

namespace ispm {

class DenoisePass final : public Pass {
  public:
    DenoisePass(const GBuffer& viewer, const gl::Texture& indirect);
    const char* getName() const override { return "denoise"; }
    // The targets follow the splat buffer's size at each execute.
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override { mProgram.reloadIfChanged(report); }
    // Radiance, or irradiance (divided by the reflectance) where leavesIrradiance.
    const gl::Texture& getOutput() const { return mTargets[kOutput].getTexture(); }
    // Whether the output is irradiance: when the filter runs on a buffer smaller than the
    // image, whose upsample (UpsamplePass) multiplies by each image pixel's own reflectance.
    static bool leavesIrradiance(const FrameInputs& inputs);

  private:
    // The output and one more target: iterations alternate between them so that the last
    // writes the output.
    static constexpr size_t kOutput = 0;
    const GBuffer& mViewer;
    const gl::Texture& mIndirect;
    ReloadableProgram mProgram;
    ParamBlocks<gpu::FilterParams> mParams{"filter parameters"}; // one per iteration
    gl::VertexArray mVertexArray;
    std::array<ColorTarget, 2> mTargets;
};

} // namespace ispm
