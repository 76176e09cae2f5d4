// DenoisePass: the splats' indirect light through `denoise` iterations of an edge-aware a-trous
// filter (steps 1, 2, 4, ... pixels of the splat buffer) guided by the viewer G-buffer; 0 passes
// it through. It works at the splat buffer's resolution; UpsamplePass follows. A first draw
// (filter_input.frag) divides the splats by the reflectance and writes the guide: the surface
// (position, normal) each buffer pixel stands for, which the filter's and the upsample's taps
// read in one fetch of a texture the buffer's size. Each iteration is a compute dispatch
// (atrous.comp) that reads its taps into shared memory.
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
    void reloadPrograms(ShaderReloadReport& report) override {
        mInputProgram.reloadIfChanged(report);
        mProgram.reloadIfChanged(report);
    }
    // Radiance, or irradiance (divided by the reflectance) where leavesIrradiance.
    const gl::Texture& getOutput() const { return mTargets[kOutput]; }
    // The guide of this frame's buffer (lib/gbuffer_filter.glsl), written unless the light
    // passed through as it was (denoise 0 at the image's resolution).
    const gl::Texture& getGuide() const { return mGuide; }
    // Whether the output is irradiance: when the buffer is smaller than the image, whose
    // upsample (UpsamplePass) multiplies by each image pixel's own reflectance.
    static bool leavesIrradiance(const FrameInputs& inputs);

  private:
    // The output and one more target: the input draw and the iterations alternate between them
    // so that the last writes the output.
    static constexpr size_t kOutput = 0;
    void resize(int width, int height); // the targets, the guide and the first draw's targets
    const GBuffer& mViewer;
    const gl::Texture& mIndirect;
    ReloadableProgram mInputProgram;
    ReloadableProgram mProgram;
    ParamBlocks<gpu::FilterParams> mParams{"filter parameters"}; // the draw's, each iteration's
    gl::VertexArray mVertexArray;
    std::array<gl::Texture, 2> mTargets; // written by the input draw and the dispatches
    gl::Texture mGuide;
    std::array<gl::Framebuffer, 2> mInputTargets; // mTargets[i]'s texture and the guide
};

} // namespace ispm
