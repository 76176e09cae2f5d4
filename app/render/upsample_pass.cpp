// Upsample: one full-screen draw at the image's resolution, or a copy when the splats were drawn
// at it.
#include "render/upsample_pass.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <shared/scene_data.h>

namespace ispm {
UpsamplePass::UpsamplePass(const GBuffer& viewer, const gl::Texture& filtered)
    : mViewer(viewer), mFiltered(filtered),
      mProgram(ReloadableProgram({.label = "upsample",
                                  .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                             {gl::ShaderStage::Fragment, "denoise/upsample.frag"}},
                                  .defines = getGBufferDefines()})),
      mVertexArray("upsample vao"), mTarget("indirect", gl::Format::RGBA32F) {}

void UpsamplePass::execute(const FrameInputs& inputs) {
    const int divisor = inputs.settings.splatDivisor;
    if (divisor == 1) {
        mTarget.getTexture().copyFrom(mFiltered);
        return;
    }
    mTarget.bind();
    gl::applyState({});
    mProgram.use();
    mVertexArray.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mFiltered.bindUnit(gpu::kUnitFilterSource);
    const gpu::FilterParams params{glm::ivec4(0, 0, 0, divisor)};
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    drawFullscreenTriangle();
}

} // namespace ispm
