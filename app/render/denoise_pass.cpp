// Denoise: the filter's input and guide, then ping-pong a-trous iterations, the last draw into
// the output target.
#include "render/denoise_pass.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <shared/scene_data.h>

#include <string>
#include <vector>

namespace ispm {

DenoisePass::DenoisePass(const GBuffer& viewer, const gl::Texture& indirect)
    : mViewer(viewer), mIndirect(indirect),
      mInputProgram(
          ReloadableProgram({.label = "filter input",
                             .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                        {gl::ShaderStage::Fragment, "denoise/filter_input.frag"}},
                             .defines = getGBufferDefines()})),
      mProgram(ReloadableProgram({.label = "denoise",
                                  .stages = {{gl::ShaderStage::Compute, "denoise/atrous.comp"}},
                                  .defines = getGBufferDefines()})),
      mVertexArray("denoise vao") {}

bool DenoisePass::leavesIrradiance(const FrameInputs& inputs) {
    return inputs.settings.splatDivisor > 1;
}

void DenoisePass::resize(int width, int height) {
    if (mGuide.getWidth() == width && mGuide.getHeight() == height) return;
    mGuide = gl::Texture::create2D("filter guide", gl::Format::RGBA32F, width, height);
    constexpr std::array<const char*, 2> kLabels = {"indirect (denoised)", "denoise intermediate"};
    for (size_t i = 0; i < mTargets.size(); ++i) {
        mTargets[i] = gl::Texture::create2D(kLabels[i], gl::Format::RGBA32F, width, height);
        mInputTargets[i] = gl::Framebuffer("filter input target " + std::to_string(i));
        mInputTargets[i].attachColor(0, mTargets[i]);
        mInputTargets[i].attachColor(1, mGuide);
        mInputTargets[i].setDrawBufferCount(2);
        mInputTargets[i].checkComplete();
    }
}

void DenoisePass::execute(const FrameInputs& inputs) {
    resize(mIndirect.getWidth(), mIndirect.getHeight());
    const int iterations = inputs.progressive.denoiseIterations;
    const int divisor = inputs.settings.splatDivisor;
    if (iterations == 0 && divisor == 1) {
        mTargets[kOutput].copyFrom(mIndirect); // the splats as they are
        return;
    }
    gl::applyState({});
    mVertexArray.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    // Block 0: the input draw's (the input and the guide); block i + 1: iteration i's dispatch.
    std::vector<gpu::FilterParams> params = {{.pixelsPerBufferPx = divisor}};
    for (int i = 0; i < iterations; ++i) {
        const bool modulate = i + 1 >= iterations && !leavesIrradiance(inputs);
        params.push_back(
            {.stepPx = 1 << i, .modulate = modulate ? 1 : 0, .pixelsPerBufferPx = divisor});
    }
    mParams.upload(params);
    const auto targetOf = [&](int draw) {
        return (iterations - draw) % 2 == 0 ? kOutput : 1 - kOutput;
    };
    mInputTargets[targetOf(0)].bind();
    mInputProgram.use();
    mIndirect.bindUnit(gpu::kUnitFilterSource);
    mParams.bind(0);
    drawFullscreenTriangle();
    mProgram.use();
    mGuide.bindUnit(gpu::kUnitFilterGuide);
    for (int i = 0; i < iterations; ++i) {
        mTargets[targetOf(i)].bindUnit(gpu::kUnitFilterSource);
        mTargets[targetOf(i + 1)].bindImage(gpu::kImageFilterOutput, false, true);
        mParams.bind(size_t(i) + 1);
        // A work group filters kFilterGroupSide^2 pixels `step` apart: step^2 lattices, each
        // split into blocks (atrous.comp).
        const auto step = static_cast<unsigned>(params[size_t(i) + 1].stepPx);
        const auto groups = [&](int size) {
            const unsigned span = gpu::kFilterGroupSide * step;
            return step * ((static_cast<unsigned>(size) + span - 1) / span);
        };
        gl::dispatchCompute(groups(mGuide.getWidth()), groups(mGuide.getHeight()));
        // The next iteration, the upsample and compose read the output as a texture; the next
        // frame's first draw renders into it.
        gl::memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::Framebuffer);
    }
}

} // namespace ispm
