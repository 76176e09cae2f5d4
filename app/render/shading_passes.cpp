// Direct, compose and tone-map passes.
#include "render/shading_passes.h"

#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"
#include "scene/settings.h"

#include <shared/scene_data.h>
#include <shared/tonemap_data.h>

#include <cstddef>

namespace ispm {

DirectPass::DirectPass(const GBuffer& viewer, const GBuffer& lights)
    : mViewer(viewer), mLights(lights),
      mTarget("direct", gl::Format::RGBA32F, "direct/direct.frag", getGBufferDefines()) {}

void DirectPass::execute(const FrameInputs& inputs) {
    inputs.scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mLights.bindTextures(gpu::kUnitLightGBufferFirst);
    mTarget.draw();
}

ComposePass::ComposePass(const GBuffer& viewer, const gl::Texture& direct,
                         const gl::Texture& indirect)
    : mViewer(viewer), mDirect(direct), mIndirect(indirect),
      mTarget("total", gl::Format::RGBA32F, "compose/compose.frag", getGBufferDefines()) {}

void ComposePass::execute(const FrameInputs& inputs) {
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mDirect.bindUnit(gpu::kUnitDirect);
    mIndirect.bindUnit(gpu::kUnitIndirect);
    mTarget.draw();
}

TonemapPass::TonemapPass(const gl::Texture& hdr)
    : mHdr(&hdr),
      mHistogram(ReloadableProgram(
          {.label = "luminance histogram",
           .stages = {{gl::ShaderStage::Compute, "tonemap/luminance_histogram.comp"}}})),
      mResolve(ReloadableProgram(
          {.label = "luminance resolve",
           .stages = {{gl::ShaderStage::Compute, "tonemap/luminance_resolve.comp"}}})),
      mExposure("exposure", sizeof(gpu::ExposureData)),
      mTarget("display", gl::Format::RGBA8, "tonemap/tonemap.frag", {}) {}

void TonemapPass::execute(const FrameInputs& inputs) {
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mExposure.bindBase(gl::BufferTarget::Storage, gpu::kBindingExposure);
    mHdr->bindUnit(gpu::kUnitHdr);
    if (!inputs.settings.luminanceMax) {
        // The histogram and counts; the white point stays for eye adaptation.
        mExposure.clearRangeToZero(0, offsetof(gpu::ExposureData, luminanceMax));
        mHistogram.use();
        const auto groups = [](int size) {
            const unsigned pixels = gpu::kExposureGroupSize * gpu::kExposurePixelsPerSide;
            return (static_cast<unsigned>(size) + pixels - 1) / pixels;
        };
        gl::dispatchCompute(groups(inputs.width), groups(inputs.height));
        gl::memoryBarrier(gl::Barrier::Storage);
        mResolve.use();
        gl::dispatchCompute(1);
        gl::memoryBarrier(gl::Barrier::Storage);
    }
    mTarget.draw();
}

float TonemapPass::readLuminanceMax() const {
    const auto data = mExposure.read<gpu::ExposureData>(1);
    return data[0].luminanceMax.x;
}

} // namespace ispm
