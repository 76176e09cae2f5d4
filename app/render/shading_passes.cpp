// Direct, compose and tone-map passes.
#include "render/shading_passes.h"

#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/light_cameras.h"
#include "render/pixel_rect.h"
#include "render/shader_root.h"
#include "scene/settings.h"

#include <shared/scene_data.h>
#include <shared/tonemap_data.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace ispm {

DirectPass::DirectPass(const GBuffer& viewer, const GBuffer& lights)
    : mViewer(viewer), mLights(lights),
      mTarget("direct", gl::Format::RGBA32F, "direct/direct.frag", getGBufferDefines()),
      mParams("direct parameters") {}

void DirectPass::execute(const FrameInputs& inputs) {
    inputs.scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mLights.bindTextures(gpu::kUnitLightGBufferFirst);
    // A light is shaded only over the pixels it can light: a shader pays for every light it
    // loops over at every pixel (llvmpipe runs both sides of each branch), so a street light
    // lighting a hundredth of the image cost as much as the sun. A box that covers more than
    // this share of the image is shaded with the whole-image lights instead, in one pass over
    // the G-buffer.
    constexpr double kWholeImageShare = 0.5;
    const double imageArea = double(inputs.width) * double(inputs.height);
    std::vector<uint32_t> whole;
    std::vector<std::pair<uint32_t, PixelRect>> parts;
    const std::vector<Light>& lights = inputs.model.lights;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        std::optional<PixelRect> rect;
        if (const std::optional<Aabb> lit = computeLitBounds(lights[i], inputs.scene.getBounds())) {
            rect = computePixelRect(*lit, inputs.clipFromWorld, inputs.width, inputs.height);
        }
        if (rect && rect->isEmpty()) continue; // it lights nothing in view
        if (rect && rect->getArea() <= kWholeImageShare * imageArea) {
            parts.emplace_back(i, *rect);
        } else {
            whole.push_back(i);
        }
    }
    // The first block writes every pixel (coverage, and black where no light is), even without
    // a whole-image light.
    // Each block's light types (lights.glsl's LIGHT_TYPES): the sun's draw compiles out the
    // point and spot lights' code, a spot's the others'.
    std::vector<gpu::DirectParams> blocks;
    std::vector<uint32_t> blockTypes;
    const auto addBlock = [&](std::span<const uint32_t> indices) {
        gpu::DirectParams b{};
        b.control =
            glm::uvec4(static_cast<uint32_t>(indices.size()), blocks.empty() ? 1u : 0u, 0u, 0u);
        uint32_t types = 0;
        for (size_t k = 0; k < indices.size(); ++k) {
            b.lights[k / 4][k % 4] = indices[k];
            types |= 1u << getGpuLightType(lights[indices[k]].type);
        }
        blocks.push_back(b);
        blockTypes.push_back(types);
    };
    size_t first = 0;
    do {
        const size_t count = std::min<size_t>(gpu::kDirectLightsPerDraw, whole.size() - first);
        addBlock(std::span(whole).subspan(first, count));
        first += count;
    } while (first < whole.size());
    const size_t wholeBlocks = blocks.size();
    for (const auto& part : parts)
        addBlock(std::span(&part.first, 1));
    mParams.upload(blocks);
    for (size_t b = 0; b < blocks.size(); ++b) {
        mParams.bind(b);
        const gl::PipelineState state{.blend = b == 0 ? gl::Blend::Off : gl::Blend::Additive};
        const std::optional<PixelRect> rect =
            b < wholeBlocks ? std::nullopt : std::optional(parts[b - wholeBlocks].second);
        std::vector<std::string> defines = inputs.scene.getSurfaceDefines();
        // A draw without lights writes coverage alone: any variant does.
        if (blockTypes[b] != 0)
            defines.push_back("LIGHT_TYPES " + std::to_string(blockTypes[b]) + "u");
        mTarget.draw(state, rect, defines);
    }
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
