// Denoise: ping-pong a-trous iterations, the last into the output target.
#include "render/denoise_pass.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <shared/scene_data.h>

#include <cstring>
#include <vector>

namespace ispm {
namespace {} // namespace

DenoisePass::DenoisePass(const GBuffer& viewer, const gl::Texture& indirect)
    : mViewer(viewer), mIndirect(indirect),
      mProgram(ReloadableProgram({.label = "denoise",
                                  .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                             {gl::ShaderStage::Fragment, "denoise/atrous.frag"}},
                                  .defines = getGBufferDefines()})),
      mVertexArray("denoise vao"),
      mTargets({ColorTarget("indirect (denoised)", gl::Format::RGBA32F),
                ColorTarget("denoise intermediate", gl::Format::RGBA32F)}) {}

bool DenoisePass::leavesIrradiance(const FrameInputs& inputs) {
    return inputs.progressive.denoiseIterations > 0 && inputs.settings.splatDivisor > 1;
}

void DenoisePass::execute(const FrameInputs& inputs) {
    const int width = mIndirect.getWidth();
    const int height = mIndirect.getHeight();
    for (ColorTarget& target : mTargets)
        target.resize(width, height);
    const int iterations = inputs.progressive.denoiseIterations;
    const int divisor = inputs.settings.splatDivisor;
    if (iterations == 0) {
        mTargets[kOutput].getTexture().copyFrom(mIndirect); // the splats as they are
        return;
    }
    gl::applyState({});
    mProgram.use();
    mVertexArray.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    std::vector<gpu::FilterParams> params(static_cast<size_t>(iterations));
    for (int i = 0; i < iterations; ++i) {
        const bool modulate = i + 1 >= iterations && !leavesIrradiance(inputs);
        params[size_t(i)].iteration = glm::ivec4(1 << i, i == 0 ? 1 : 0, modulate ? 1 : 0, divisor);
    }
    mParams.upload(params);
    const gl::Texture* source = &mIndirect;
    for (int i = 0; i < iterations; ++i) {
        const size_t target = (iterations - 1 - i) % 2 == 0 ? kOutput : 1 - kOutput;
        mTargets[target].bind();
        source->bindUnit(gpu::kUnitFilterSource);
        mParams.bind(size_t(i));
        drawFullscreenTriangle();
        source = &mTargets[target].getTexture();
    }
}

} // namespace ispm
