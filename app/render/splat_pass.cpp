// Splatting, and the warning on splat discs too wide for the scene.
#include "render/splat_pass.h"

#include "core/strings.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"

#include <shared/gather_data.h>
#include <shared/photon_data.h>
#include <shared/scene_data.h>
#include <shared/splat_clip.h>

#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <vector>

namespace ispm {
namespace {

// The unit cube's 12 triangles over its 8 corners (splat.vert: corner i has x from bit 0, y from
// bit 1, z from bit 2, each -1 or +1), counter-clockwise seen from outside.
constexpr std::array<uint32_t, gpu::kSplatCubeVertices> kCubeIndices = {
    0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
    2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
// The disc's square: 2 triangles over the cube's corners 0-3, its bottom face. (Padded with
// degenerate triangles to the cube's count, so that one draw command served both shapes, the
// disc paid llvmpipe's setup for 10 empty triangles a photon: a fifth of the Cornell box's
// splat at 256x256.)
constexpr std::array<uint32_t, gpu::kSplatDiscIndices> kDiscIndices = {0, 1, 3, 0, 3, 2};

// Pixels across a tile of llvmpipe's rasteriser, which bins and shades each tile on one thread.
constexpr int kRasterTilePx = 64;
// The list's first size (slots: 1 MiB); it grows to 1.5x a frame's need when a frame needs more.
constexpr size_t kInitialListSlots = size_t(1) << 18;
constexpr double kListGrowth = 1.5;

ReloadableProgram buildComputeProgram(const char* label, const char* path,
                                      std::vector<std::string> defines) {
    return ReloadableProgram({.label = label,
                              .stages = {{gl::ShaderStage::Compute, path}},
                              .defines = std::move(defines)});
}

unsigned divideRoundingUp(unsigned n, unsigned d) {
    return (n + d - 1) / d;
}

} // namespace

std::string describeOversizedSplats(double surfaceAreaM2, float diagonalM,
                                    const FrameSettings& settings) {
    constexpr float kMaxShareOfDiagonal = 0.2f;
    if (settings.radiusMode == gpu::kRadiusDensity || !settings.hasIndirect()) return "";
    const SplatRadii r =
        computeSplatRadii(surfaceAreaM2, diagonalM, settings, settings.radiusScale);
    const float largest = std::max(r.radiusMinM, r.radiusMaxM);
    if (!(largest > kMaxShareOfDiagonal * diagonalM)) return "";
    return strCat("splat discs reach a radius of ", largest,
                  " m (radius_max x radius_scale) in a "
                  "scene ",
                  diagonalM,
                  " m across: most of their light falls where no surface "
                  "is and the indirect light fades; lower radius_scale or radius_max, or use "
                  "radius_mode=density");
}

SplatPass::SplatPass(const GBuffer& viewer, const PhotonBuffers& buffers,
                     const PhotonDensityPass& density)
    : mViewer(viewer), mBuffers(buffers), mDensity(density),
      mPrograms({.label = "splat",
                 .stages = {{gl::ShaderStage::Vertex, "splat/splat.vert"},
                            {gl::ShaderStage::Fragment, "splat/splat.frag"}},
                 .defines = getGBufferDefines()}),
      mCubeVertexArray("splat cube vao"), mDiscVertexArray("splat disc vao"),
      mCubeIndices(gl::Buffer::fromSpan<uint32_t>("splat cube indices", kCubeIndices)),
      mDiscIndices(gl::Buffer::fromSpan<uint32_t>("splat disc indices", kDiscIndices)),
      mBinCount(buildComputeProgram("gather bin count", "splat/gather_bin.comp", {})),
      mBinFill(buildComputeProgram("gather bin fill", "splat/gather_bin.comp", {"FILL"})),
      mScan(buildComputeProgram("gather scan", "splat/gather_scan.comp", {})),
      mGather(buildComputeProgram("gather", "splat/gather.comp", getGBufferDefines())),
      mGatherParams("gather parameters", sizeof(gpu::GatherParams)) {
    // Indexed: the vertex stage runs once per corner (8), not per triangle corner (36).
    mCubeVertexArray.setElementBuffer(mCubeIndices);
    mDiscVertexArray.setElementBuffer(mDiscIndices);
}

bool SplatPass::separatesCaustics(const FrameSettings& settings) {
    return settings.radiusMode == gpu::kRadiusDensity;
}

namespace {

void resizeTarget(gl::Texture& texture, gl::Framebuffer& framebuffer, const char* label, int width,
                  int height) {
    if (texture.getWidth() == width && texture.getHeight() == height) return;
    texture = gl::Texture::create2D(label, gl::Format::RGBA32F, width, height);
    framebuffer = gl::Framebuffer(strCat(label, " target"));
    framebuffer.attachColor(0, texture);
    framebuffer.setDrawBufferCount(1);
    framebuffer.checkComplete();
}

} // namespace

glm::ivec2 SplatPass::computeTargetOffset(glm::ivec2 size) {
    // Across only: four tiles bin each splat up to four times, and the splat of small buffers is
    // bound by the vertex stage and binning, which llvmpipe runs on one thread (courtyard outside
    // at 1/4, 10,000 photons: 13.3 ms in one tile, 9.0 in two, 11.0 in four).
    return {size.x < 2 * kRasterTilePx ? kRasterTilePx - size.x / 2 : 0, 0};
}

void SplatPass::resizeBuffers(const FrameInputs& inputs) {
    const glm::ivec2 size = inputs.settings.splatSize;
    resizeTarget(mIndirect, mFramebuffer, "indirect", size.x, size.y);
    const glm::ivec2 offset = computeTargetOffset(size);
    if (offset != glm::ivec2(0))
        resizeTarget(mTarget, mTargetFramebuffer, "splat target", offset.x + size.x,
                     offset.y + size.y);
    // The caustic buffer exists where it is drawn and read (radius_mode density): 1x1 elsewhere,
    // so the upsample's unused sampler still has a texture.
    const bool apart = separatesCaustics(inputs.settings);
    resizeTarget(mCaustics, mCausticFramebuffer, "caustics", apart ? inputs.width : 1,
                 apart ? inputs.height : 1);
}

void SplatPass::clear(const FrameInputs& inputs) {
    resizeBuffers(inputs);
    mFramebuffer.clearColor(0, glm::vec4(0.0f));
    if (separatesCaustics(inputs.settings)) mCausticFramebuffer.clearColor(0, glm::vec4(0.0f));
}

void SplatPass::executeGather(const FrameInputs& inputs) {
    const glm::ivec2 size = inputs.settings.splatSize;
    clear(inputs); // the caustic buffer, which the gather does not write
    const unsigned tilesX = divideRoundingUp(unsigned(size.x), gpu::kGatherTilePx);
    const unsigned tilesY = divideRoundingUp(unsigned(size.y), gpu::kGatherTilePx);
    const size_t tileBytes = sizeof(glm::uvec4) + size_t(tilesX) * tilesY * sizeof(gpu::GatherTile);
    if (mTiles.getSize() < tileBytes) mTiles = gl::Buffer("gather tiles", tileBytes);
    mTiles.clearToZero();
    gpu::GatherParams params{.tiles = glm::uvec2(tilesX, tilesY),
                             .tileCount = tilesX * tilesY,
                             .clipLines = inputs.settings.splatClip ? 1u : 0u,
                             .bufferSizePx = glm::uvec2(size),
                             .pixelsPerBufferPx = uint32_t(inputs.settings.splatDivisor),
                             .photons = separatesCaustics(inputs.settings)
                                            ? gpu::kSplatDiffusePhotons
                                            : gpu::kSplatAllPhotons,
                             .squash = inputs.settings.squash};
    mGatherParams.upload(0, sizeof(params), &params);
    mGatherParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mBuffers.bind();
    mDensity.getClip().bindBase(gl::BufferTarget::Storage, gpu::kBindingSplatClip);
    mTiles.bindBase(gl::BufferTarget::Storage, gpu::kBindingGatherTiles);
    const unsigned binGroups =
        divideRoundingUp(mBuffers.getResultCapacity(), gpu::kGatherBinGroupSize);
    mBinCount.use();
    gl::dispatchCompute(binGroups);
    gl::memoryBarrier(gl::Barrier::Storage);
    mScan.use();
    gl::dispatchCompute(1);
    gl::memoryBarrier(gl::Barrier::Storage | gl::Barrier::BufferUpdate);
    // The list's length is known only now: read it (a wait for the GPU) and grow the list when
    // this frame needs more than it holds, so no photon is ever dropped from a tile.
    const size_t slots = mTiles.read<uint32_t>(1)[0];
    if (slots * sizeof(uint32_t) > mList.getSize()) {
        const auto grown = std::max(kInitialListSlots, size_t(double(slots) * kListGrowth));
        mList = gl::Buffer("gather list", grown * sizeof(uint32_t));
    }
    mList.bindBase(gl::BufferTarget::Storage, gpu::kBindingGatherList);
    mBinFill.use();
    gl::dispatchCompute(binGroups);
    gl::memoryBarrier(gl::Barrier::Storage);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mIndirect.bindImage(gpu::kImageGatherOutput, false, true);
    mGather.use();
    gl::dispatchCompute(tilesX, tilesY);
    gl::memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::Framebuffer);
    if (!separatesCaustics(inputs.settings)) return;
    // The caustic photons as the raster draws them.
    uploadParams(inputs);
    bindRaster(inputs);
    drawCaustics(inputs);
    gl::applyState({});
}

void SplatPass::execute(const FrameInputs& inputs) {
    if (inputs.settings.splatMode == gpu::kSplatModeGather) {
        executeGather(inputs);
        return;
    }
    executeDraws(inputs, 0, inputs.splatDraws);
}

void SplatPass::uploadParams(const FrameInputs& inputs) {
    const uint32_t draws = inputs.splatDraws;
    const bool apart = separatesCaustics(inputs.settings);
    std::vector<gpu::SplatParams> params(size_t(draws) + 1);
    for (uint32_t p = 0; p <= draws; ++p) {
        const bool caustic = p == draws; // at the image's resolution, its photons from the list
        params[p].clipLines = inputs.settings.splatClip ? 1u : 0u;
        params[p].shape = inputs.settings.splatShape;
        params[p].draw = p;
        params[p].drawCount = draws;
        params[p].squash = inputs.settings.squash;
        params[p].pixelsPerBufferPx = caustic ? 1 : inputs.settings.splatDivisor;
        params[p].targetOffsetPx =
            caustic ? glm::ivec2(0) : computeTargetOffset(inputs.settings.splatSize);
        params[p].photons = !apart    ? gpu::kSplatAllPhotons
                            : caustic ? gpu::kSplatCausticPhotons
                                      : gpu::kSplatDiffusePhotons;
        params[p].discList = drawsDiscList(inputs) && !caustic ? 1u : 0u;
    }
    mParams.upload(params);
}

void SplatPass::bindRaster(const FrameInputs& inputs) {
    // Additive float accumulation. A flat disc covers a pixel once from either side; of a box,
    // only the back faces count.
    const bool isBox = inputs.settings.splatShape == gpu::kSplatShapeBox;
    gl::applyState({.blend = gl::Blend::Additive, .cull = isBox ? gl::Cull::Front : gl::Cull::Off});
    std::vector<std::string> defines = inputs.scene.getSurfaceDefines();
    defines.push_back(inputs.settings.splatClip ? "SPLAT_CLIP_LINES 1" : "SPLAT_CLIP_LINES 0");
    defines.push_back(inputs.scene.hasNormalMaps() ? "SCENE_NORMAL_MAPS 1" : "SCENE_NORMAL_MAPS 0");
    mPrograms.get(defines).use();
    (isBox ? mCubeVertexArray : mDiscVertexArray).bind();
    mBuffers.bind();
    mDensity.getClip().bindBase(gl::BufferTarget::Storage, gpu::kBindingSplatClip);
    const gl::Buffer& list = mDensity.getCausticList();
    const size_t offset = mDensity.getCausticOffset();
    if (offset < list.getSize())
        list.bindRange(gl::BufferTarget::Storage, gpu::kBindingCausticList, offset,
                       list.getSize() - offset);
    const size_t discs = mDensity.getDiscOffset();
    if (drawsDiscList(inputs) && discs < list.getSize())
        list.bindRange(gl::BufferTarget::Storage, gpu::kBindingDiscList, discs,
                       list.getSize() - discs);
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
}

bool SplatPass::drawsDiscList(const FrameInputs& inputs) {
    return inputs.settings.radiusMode == gpu::kRadiusDensity;
}

void SplatPass::drawSplats(uint32_t p) {
    mParams.bind(p);
    gl::drawElementsIndirect(gl::Primitive::Triangles, mBuffers.getSplatDraws(),
                             p * gpu::kSplatDrawUvec4s * sizeof(glm::uvec4));
}

void SplatPass::drawCaustics(const FrameInputs& inputs) {
    mCausticFramebuffer.bind();
    mParams.bind(inputs.splatDraws);
    gl::drawElementsIndirect(gl::Primitive::Triangles, mDensity.getCausticList(),
                             mDensity.getCausticOffset());
}

void SplatPass::executeDraws(const FrameInputs& inputs, uint32_t firstDraw, uint32_t drawCount) {
    assert(inputs.settings.splatMode != gpu::kSplatModeGather);
    assert(firstDraw + drawCount <= inputs.splatDraws && inputs.splatDraws <= gpu::kMaxSplatDraws);
    // Every draw's blocks are uploaded with the first: a later slice binds its own.
    if (firstDraw == 0) {
        clear(inputs);
        uploadParams(inputs);
    }
    bindRaster(inputs);
    const glm::ivec2 size = inputs.settings.splatSize;
    const glm::ivec2 offset = computeTargetOffset(size);
    const bool atOffset = offset != glm::ivec2(0);
    if (atOffset) {
        if (firstDraw == 0) mTargetFramebuffer.clearColor(0, glm::vec4(0.0f));
        mTargetFramebuffer.bind();
        gl::setViewport(offset.x, offset.y, size.x, size.y);
    } else {
        mFramebuffer.bind();
    }
    for (uint32_t p = firstDraw; p < firstDraw + drawCount; ++p)
        drawSplats(p);
    if (atOffset && firstDraw + drawCount == inputs.splatDraws)
        mIndirect.copyFrom(mTarget, offset.x, offset.y);
    // The caustic photons (few, small discs) in one draw, with the first slice.
    if (firstDraw == 0 && separatesCaustics(inputs.settings)) drawCaustics(inputs);
    gl::applyState({});
}

} // namespace ispm
