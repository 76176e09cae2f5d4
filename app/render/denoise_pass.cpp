// Denoise: ping-pong a-trous iterations, the last into the output target.
#include "render/denoise_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/splat_pass.h"
#include "scene/settings.h"

#include <shared/scene_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

constexpr GLint kLocationIteration = 0; // shaders/denoise/atrous.frag
// Image size whose derived filter is one iteration wide (steps of 1 pixel, +-2 pixels): at
// 256 px three iterations reach +-14 pixels, about 5% of the image, where the splats' noise is.
constexpr double kPixelsPerIteration = 32.0;
// At most three derived iterations: each costs 25 taps a pixel (1.2 s at 1280x1024 for five on
// llvmpipe); larger images keep the filter's reach in pixels, not in image fractions.
constexpr int kMaxDerivedIterations = 3;

} // namespace

int computeDenoiseIterations(const Settings& settings, int width, int height) {
    if (settings.isSet("denoise")) return settings.getInt("denoise");
    const double iterations = std::log2(double(std::min(width, height)) / kPixelsPerIteration);
    return std::clamp(int(std::lround(iterations)), 0, kMaxDerivedIterations);
}

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
    for (ColorTarget& target : mTargets) target.resize(width, height);
    const int iterations = computeDenoiseIterations(inputs.settings, width, height);
    const int divisor = computeSplatDivisor(inputs.settings, inputs.width, inputs.height);
    if (iterations == 0) {
        mTargets[kOutput].getTexture().copyFrom(mIndirect); // the splats as they are
        return;
    }
    gl::applyState({});
    mProgram.use();
    mVertexArray.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    const gl::Texture* source = &mIndirect;
    for (int i = 0; i < iterations; ++i) {
        const bool last = i + 1 >= iterations;
        const size_t target = (iterations - 1 - i) % 2 == 0 ? kOutput : 1 - kOutput;
        mTargets[target].bind();
        source->bindUnit(gpu::kUnitFilterSource);
        glUniform4i(kLocationIteration, 1 << i, i == 0 ? 1 : 0, last ? 1 : 0, divisor);
        drawFullscreenTriangle();
        source = &mTargets[target].getTexture();
    }
}

} // namespace ispm
