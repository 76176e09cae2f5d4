// Direct, compose and tone-map passes.
#include "render/shading_passes.h"

#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/light_cameras.h"
#include "render/pixel_rect.h"
#include "render/shader_root.h"
#include "settings/settings.h"

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

namespace {

// One draw of the direct pass: its parameter block, its lights' types (bits 1 << kLight*) and
// the pixels it covers (none: the whole image).
struct DirectDraw {
    gpu::DirectParams params{};
    uint32_t lightTypes = 0;
    std::optional<PixelRect> rect;
};

// A light is shaded only over the pixels it can light: a shader pays for every light it loops
// over at every pixel (llvmpipe runs both sides of each branch), so a street light lighting a
// hundredth of the image cost as much as the sun. Lights that reach every direction, and those
// whose box covers more than kWholeImageShare of the image, share whole-image draws (one pass
// over the G-buffer for all of them); each other light gets a draw over its rectangle. The first
// draw writes every pixel (coverage, and black where no light is), even without a light.
std::vector<DirectDraw> planDirectDraws(const FrameInputs& inputs) {
    constexpr double kWholeImageShare = 0.5;
    const double imageArea = double(inputs.width) * double(inputs.height);
    const std::vector<Light>& lights = inputs.model.lights;
    std::vector<uint32_t> whole;
    std::vector<std::pair<uint32_t, PixelRect>> parts;
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
    std::vector<DirectDraw> draws;
    const auto addDraw = [&](std::span<const uint32_t> indices, std::optional<PixelRect> rect) {
        DirectDraw d;
        d.params.lightCount = static_cast<uint32_t>(indices.size());
        d.params.firstDraw = draws.empty() ? 1u : 0u;
        for (size_t k = 0; k < indices.size(); ++k) {
            d.params.lights[k / 4][k % 4] = indices[k];
            d.lightTypes |= 1u << getGpuLightType(lights[indices[k]].type);
        }
        d.rect = rect;
        draws.push_back(d);
    };
    size_t first = 0;
    do {
        const size_t count = std::min<size_t>(gpu::kDirectLightsPerDraw, whole.size() - first);
        addDraw(std::span(whole).subspan(first, count), std::nullopt);
        first += count;
    } while (first < whole.size());
    for (const auto& [light, rect] : parts)
        addDraw(std::span(&light, 1), rect);
    return draws;
}

// The defines of direct.frag and edge_shade.comp: the scene's reflection model, how shadows are
// found, and the scene's ray tests.
std::vector<std::string> getTracingDefines(const FrameInputs& inputs) {
    std::vector<std::string> defines = inputs.scene.getSurfaceDefines();
    defines.push_back(getShadowRaysDefine(inputs.settings));
    const std::vector<std::string> rays = inputs.scene.getRayDefines();
    defines.insert(defines.end(), rays.begin(), rays.end());
    return defines;
}

} // namespace

DirectPass::DirectPass(const GBuffer& viewer, const GBuffer& lights)
    : mViewer(viewer), mLights(lights),
      mTarget("direct", gl::Format::RGBA32F, "direct/direct.frag", getGBufferDefines()),
      mParams("direct parameters"),
      mEdgeFind({.label = "direct light edges",
                 .stages = {{gl::ShaderStage::Compute, "direct/edge_find.comp"}},
                 .defines = getGBufferDefines()}),
      mEdgeShade({.label = "direct light over edge pixels",
                  .stages = {{gl::ShaderStage::Compute, "direct/edge_shade.comp"}},
                  .defines = getGBufferDefines()}),
      mEdgeParams("direct edge parameters", sizeof(gpu::DirectEdgeParams)) {}

void DirectPass::execute(const FrameInputs& inputs) {
    inputs.scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mLights.bindTextures(gpu::kUnitLightGBufferFirst);
    const std::vector<DirectDraw> draws = planDirectDraws(inputs);
    std::vector<gpu::DirectParams> blocks;
    for (const DirectDraw& d : draws) {
        blocks.push_back(d.params);
        blocks.back().rayFloorM = inputs.scene.getRayEpsilon();
    }
    mParams.upload(blocks);
    for (size_t i = 0; i < draws.size(); ++i) {
        mParams.bind(i);
        // Each draw compiles in its lights' types (lights.glsl's LIGHT_TYPES): the sun's
        // compiles out the point and spot lights' code, a spot's the others'. A draw without
        // lights writes coverage alone: the plain program does.
        std::vector<std::string> defines = getTracingDefines(inputs);
        if (draws[i].lightTypes != 0)
            defines.push_back("LIGHT_TYPES " + std::to_string(draws[i].lightTypes) + "u");
        // The first draw shades the emitting triangles and the environment too (direct.frag).
        if (i == 0 && (inputs.scene.getEmitterCount() > 0 || inputs.model.environment.isSet())) {
            defines.emplace_back("EMITTERS 1");
        }
        mTarget.draw({.blend = i == 0 ? gl::Blend::Off : gl::Blend::Additive}, draws[i].rect,
                     defines);
    }
    if (inputs.settings.edgeSamples > 0) shadeEdges(inputs);
}

void DirectPass::shadeEdges(const FrameInputs& inputs) {
    constexpr unsigned kFindGroupSide = 8; // edge_find.comp's local size
    // Room for every pixel (the header, then one uint each), only once edges are shaded. A pixel's
    // index leaves the top two bits for its halvings: 16384^2 (the largest image) is 2^28.
    const size_t bytes = sizeof(gpu::DirectEdgeHeader) + sizeof(uint32_t) *
                                                             static_cast<size_t>(inputs.width) *
                                                             static_cast<size_t>(inputs.height);
    if (mEdges.getSize() != bytes) mEdges = gl::Buffer("direct edge pixels", bytes);
    const gpu::DirectEdgeHeader cleared{.groupsX = 0, .groupsY = 1, .groupsZ = 1, .pixels = 0};
    mEdges.upload(0, sizeof(cleared), &cleared);
    mEdges.bindBase(gl::BufferTarget::Storage, gpu::kBindingDirectEdges);
    mTarget.getTexture().bindUnit(gpu::kUnitDirect);
    // The emission channel exists in scenes with an emitter (getSceneGBufferChannels).
    const std::string edgeEmission =
        inputs.scene.hasEmission() ? "EDGE_EMISSION 1" : "EDGE_EMISSION 0";
    mEdgeFind.get({edgeEmission}).use();
    gl::dispatchCompute((static_cast<unsigned>(inputs.width) + kFindGroupSide - 1) / kFindGroupSide,
                        (static_cast<unsigned>(inputs.height) + kFindGroupSide - 1) /
                            kFindGroupSide);
    // The list and the dispatch's group count are written; the direct light is read before it
    // is rewritten (the list holds each pixel once, and a pixel reads its neighbours only here).
    gl::memoryBarrier(gl::Barrier::Storage | gl::Barrier::Command);
    gpu::DirectEdgeParams params{};
    params.samplesPerPixel = static_cast<uint32_t>(inputs.settings.edgeSamples);
    params.rayFloorM = inputs.scene.getRayEpsilon();
    mEdgeParams.upload(0, sizeof(params), &params);
    mEdgeParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    std::vector<std::string> defines = getTracingDefines(inputs);
    defines.push_back(edgeEmission);
    mEdgeShade.get(defines).use();
    mTarget.getTexture().bindImage(gpu::kImageDirect, false, true);
    gl::dispatchComputeIndirect(mEdges, 0);
    // Compose and accumulate read the rewritten pixels as textures.
    gl::memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::ImageAccess);
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
    // Without an emitter the emission channel holds zero (getSceneGBufferChannels): not read.
    const bool environment = inputs.model.environment.isSet();
    if (environment) inputs.scene.bind(); // the environment's block
    mTarget.draw({}, std::nullopt,
                 {inputs.scene.hasEmission() ? "COMPOSE_EMISSION 1" : "COMPOSE_EMISSION 0",
                  environment ? "COMPOSE_ENVIRONMENT 1" : "COMPOSE_ENVIRONMENT 0"});
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
