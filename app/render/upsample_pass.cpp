// Upsample: one full-screen draw at the image's resolution, or a copy when the splats were drawn
// at it and no caustic light is added.
#include "render/upsample_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/splat_pass.h"

#include <shared/scene_data.h>

namespace ispm {
UpsamplePass::UpsamplePass(const GBuffer& viewer, const gl::Texture& filtered,
                           const gl::Texture& guide, const gl::Texture& caustics)
    : mViewer(viewer), mFiltered(filtered), mGuide(guide), mCaustics(caustics),
      mPrograms({.label = "upsample",
                 .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                            {gl::ShaderStage::Fragment, "denoise/upsample.frag"}},
                 .defines = getGBufferDefines()}),
      mVertexArray("upsample vao"), mTarget("indirect", gl::Format::RGBA32F) {}

void UpsamplePass::execute(const FrameInputs& inputs) {
    const int divisor = inputs.settings.splatDivisor;
    const bool caustics = SplatPass::separatesCaustics(inputs.settings);
    if (divisor == 1 && !caustics) {
        mTarget.getTexture().copyFrom(mFiltered);
        return;
    }
    mTarget.bind();
    gl::applyState({});
    mPrograms
        .get({caustics ? "UPSAMPLE_CAUSTICS 1" : "UPSAMPLE_CAUSTICS 0",
              divisor > 1 ? "UPSAMPLE_FILTER 1" : "UPSAMPLE_FILTER 0"})
        .use();
    mVertexArray.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mFiltered.bindUnit(gpu::kUnitFilterSource);
    mGuide.bindUnit(gpu::kUnitFilterGuide);
    mCaustics.bindUnit(gpu::kUnitCaustics);
    // Irradiance from a smaller buffer (DenoisePass::leavesIrradiance); at the image's
    // resolution the light passes through as it is.
    const gpu::FilterParams params{.pixelsPerBufferPx = divisor};
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    drawFullscreenTriangle();
}

} // namespace ispm
