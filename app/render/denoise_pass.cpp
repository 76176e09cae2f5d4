// Denoise: ping-pong a-trous iterations, the last into the output target.
#include "render/denoise_pass.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <shared/scene_data.h>

#include <cstring>
#include <vector>

namespace ispm {
namespace {

// Each iteration's FilterParams sits at its own multiple of this in one buffer, bound by range
// (the largest UNIFORM_BUFFER_OFFSET_ALIGNMENT the GL allows an implementation to require).
constexpr size_t kParamsStride = 256;

} // namespace

DenoisePass::DenoisePass(const GBuffer& viewer, const gl::Texture& indirect)
    : mViewer(viewer), mIndirect(indirect),
      mProgram(ReloadableProgram({.label = "denoise",
                                  .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                             {gl::ShaderStage::Fragment, "denoise/atrous.frag"}},
                                  .defines = getGBufferDefines()})),
      mVertexArray("denoise vao"),
      mTargets({ColorTarget("indirect (denoised)", gl::Format::RGBA32F),
                ColorTarget("denoise intermediate", gl::Format::RGBA32F)}) {}

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
    std::vector<uint8_t> params(size_t(iterations) * kParamsStride, 0);
    for (int i = 0; i < iterations; ++i) {
        const bool last = i + 1 >= iterations;
        const gpu::FilterParams block{glm::ivec4(1 << i, i == 0 ? 1 : 0, last ? 1 : 0, divisor)};
        std::memcpy(params.data() + size_t(i) * kParamsStride, &block, sizeof block);
    }
    if (mParams.getSize() < params.size()) mParams = gl::Buffer("filter parameters", params.size());
    mParams.upload(0, params.size(), params.data());
    const gl::Texture* source = &mIndirect;
    for (int i = 0; i < iterations; ++i) {
        const size_t target = (iterations - 1 - i) % 2 == 0 ? kOutput : 1 - kOutput;
        mTargets[target].bind();
        source->bindUnit(gpu::kUnitFilterSource);
        mParams.bindRange(gl::BufferTarget::Uniform, gpu::kBindingPassParams,
                          size_t(i) * kParamsStride, sizeof(gpu::FilterParams));
        drawFullscreenTriangle();
        source = &mTargets[target].getTexture();
    }
}

} // namespace ispm
