// Density radii: clear the hashed grid, count the result photons into it, then set each radius.
#include "render/photon_density_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/gbuffer.h"
#include "render/gpu_scene.h"
#include "render/splat_radii.h"

#include <shared/photon_data.h>
#include <shared/scene_data.h>
#include <shared/splat_clip.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace ispm {
namespace {

// Fractions of the evenly-spread radius (computeEvenRadius): the finest cell, the largest radius.
constexpr float kFinestCellFraction = 1.0f / 16.0f;
constexpr float kMaxRadiusFactor = 4.0f;
// Offsets of the lists in the cells buffer: a multiple of the largest storage-buffer offset
// alignment the GL allows (GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT), so splat.vert can bind
// the disc list by range.
constexpr size_t kListAlignment = 256;
// Hashed slots per stored photon: each photon lands in one cell per level, distinct at the
// finest few levels; 8 slots keep the table under 70% full at capacity.
constexpr uint32_t kSlotsPerPhoton = 8;
static_assert(gpu::kClipRays == 8, "photon_density.comp holds the clip rays in two vec4s");

} // namespace

float computeEvenRadius(double surfaceAreaM2, int photons, int neighbours) {
    const double evenRadius =
        std::sqrt(double(neighbours) * surfaceAreaM2 / (glm::pi<double>() * std::max(photons, 1)));
    return std::max(float(evenRadius), std::numeric_limits<float>::min());
}

float computeDensityRadiusMax(double surfaceAreaM2, int photons, int neighbours) {
    return kMaxRadiusFactor * computeEvenRadius(surfaceAreaM2, photons, neighbours);
}

PhotonDensityPass::PhotonDensityPass(PhotonBuffers& buffers, const GBuffer& viewer)
    : mBuffers(buffers), mViewer(viewer),
      mPrograms({.label = "photon density",
                 .stages = {{gl::ShaderStage::Compute, "photon/photon_density.comp"}},
                 .defines = getGBufferDefines()}),
      mOrderPrograms({.label = "photon order",
                      .stages = {{gl::ShaderStage::Compute, "photon/photon_order.comp"}}}),
      mDiscDraws({.label = "photon prepare (discs)",
                  .stages = {{gl::ShaderStage::Compute, "photon/photon_prepare.comp"}},
                  .defines = {"DISC_DRAWS 1"}}),
      mPrepareParams("photon prepare parameters (discs)", sizeof(gpu::PrepareParams)),
      mParams("photon density parameters", sizeof(gpu::DensityParams)),
      mOrderParams("photon order parameters", sizeof(gpu::OrderParams)) {}

void PhotonDensityPass::setTravelRadii(const FrameInputs& inputs, glm::uvec2 slice) {
    const SplatRadii r = computeSplatRadii(inputs.scene.getSurfaceArea(),
                                           glm::length(inputs.scene.getBounds().getExtent()),
                                           inputs.settings, inputs.getRadiusScale());
    gpu::DensityParams params{};
    params.stage = gpu::kDensityStageTravelCull;
    params.radiusMode = inputs.settings.radiusMode;
    params.travel = {.radiusMinM = r.radiusMinM,
                     .radiusMaxM = r.radiusMaxM,
                     .distMinM = r.distMinM,
                     .distMaxM = r.distMaxM};
    params.radiusScale = 1.0f;
    params.rayOffsetM = inputs.scene.getRayEpsilon(); // the clip's rays
    params.slice = slice.x;
    params.slices = slice.y;
    params.squash = inputs.settings.squash;
    runTravelStage(inputs, params);
}

void PhotonDensityPass::sumLightPower(const FrameInputs& inputs, glm::uvec2 slice) {
    const size_t bytes =
        size_t(std::max(inputs.scene.getPhotonSourceCount(), 1u)) * 2 * sizeof(uint32_t);
    if (mLightPower.getSize() != bytes) mLightPower = gl::Buffer("photon power per light", bytes);
    if (slice.x == 0) mLightPower.clearToZero();
    gpu::DensityParams params{};
    params.stage = gpu::kDensityStageTravelPower;
    params.radiusMode = inputs.settings.radiusMode;
    params.slice = slice.x;
    params.slices = slice.y;
    runTravelStage(inputs, params);
}

void PhotonDensityPass::runTravelStage(const FrameInputs& inputs,
                                       const gpu::DensityParams& params) {
    mParams.upload(0, sizeof(params), &params);
    // No table: the lights' sums with widen_strong, and for the cull with splat_clip the scene,
    // against which it clips the discs in view.
    mBuffers.bind();
    if (inputs.settings.widenStrong)
        mLightPower.bindBase(gl::BufferTarget::Storage, gpu::kBindingDensityCells);
    if (inputs.settings.splatClip && params.stage == gpu::kDensityStageTravelCull) {
        reserveClip();
        inputs.scene.bind();
        mClip.bindBase(gl::BufferTarget::Storage, gpu::kBindingSplatClip);
    }
    if (measuresSurfaceEnds(params.stage, inputs.settings))
        mViewer.bindTextures(gpu::kUnitGBufferFirst);
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    useStage(params.stage, inputs.settings);
    dispatch(glm::uvec2(params.slice, params.slices));
    // The cull stage reads the lights' sums; the splat's vertex stage reads the radii.
    gl::memoryBarrier(gl::Barrier::Storage);
}

bool PhotonDensityPass::measuresSurfaceEnds(uint32_t stage, const FrameSettings& settings) {
    return settings.surfaceEnds &&
           (stage == gpu::kDensityStageRadius || stage == gpu::kDensityStageTravelCull);
}

void PhotonDensityPass::useStage(uint32_t stage, const FrameSettings& settings) {
    mPrograms
        .get({"DENSITY_STAGE " + std::to_string(stage) + "u",
              settings.splatClip ? "CLIP_DISCS 1" : "CLIP_DISCS 0",
              settings.widenStrong ? "WIDEN_STRONG 1" : "WIDEN_STRONG 0",
              settings.splatMerge > 0.0f ? "MERGE_DISCS 1" : "MERGE_DISCS 0",
              measuresSurfaceEnds(stage, settings) ? "SURFACE_ENDS 1" : "SURFACE_ENDS 0"})
        .use();
}

void PhotonDensityPass::reserveClip() {
    const size_t bytes =
        size_t(std::max(mBuffers.getFrameResults(), 1u)) * gpu::kClipVec4s * sizeof(glm::vec4);
    if (mClip.getSize() < bytes) mClip = gl::Buffer("splat clip distances", bytes);
}

void PhotonDensityPass::dispatch(glm::uvec2 slice) const {
    if (slice.y == 1) {
        gl::dispatchComputeIndirect(mBuffers.getCounters(),
                                    offsetof(gpu::PhotonCounters, densityDispatch));
        return;
    }
    // The stored photons: the splat's instance count.
    const size_t stored = offsetof(gpu::PhotonCounters, splatDraw) + sizeof(uint32_t);
    mBuffers.dispatchSlice(stored, slice.x, slice.y);
}

gpu::OrderParams makeOrderParams(const Aabb& bounds, size_t countsAt, size_t orderAt) {
    const glm::vec3 extent = glm::max(bounds.getExtent(), glm::vec3(1e-6f));
    return {.loW = bounds.lo,
            .countsAt = uint32_t(countsAt),
            .cellsPerM = float(1u << gpu::kOrderAxisBits) / extent,
            .orderAt = uint32_t(orderAt)};
}

void PhotonDensityPass::sortPhotons(const FrameInputs& inputs, size_t countsAt, size_t orderAt) {
    const gpu::OrderParams params = makeOrderParams(inputs.scene.getBounds(), countsAt, orderAt);
    mOrderParams.upload(0, sizeof(params), &params);
    mBuffers.bind();
    mCells.bindBase(gl::BufferTarget::Storage, gpu::kBindingDensityCells);
    mOrderParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    for (uint32_t stage : {gpu::kOrderStageCount, gpu::kOrderStageScan, gpu::kOrderStageScatter}) {
        mOrderPrograms.get({"ORDER_STAGE " + std::to_string(stage) + "u"}).use();
        if (stage == gpu::kOrderStageScan)
            gl::dispatchCompute(1);
        else
            dispatch(glm::uvec2(0u, 1u)); // every stored photon
        gl::memoryBarrier(gl::Barrier::Storage);
    }
}

uint32_t PhotonDensityPass::getStageCount(const FrameSettings& settings) {
    // Count, radius, and with splat_merge the merge.
    if (settings.radiusMode == gpu::kRadiusDensity) return settings.splatMerge > 0.0f ? 3u : 2u;
    return settings.widenStrong ? 2u : 1u;
}

void PhotonDensityPass::execute(const FrameInputs& inputs) {
    for (uint32_t stage = 0; stage < getStageCount(inputs.settings); ++stage)
        executeSlice(inputs, stage, 0, 1);
}

void PhotonDensityPass::executeSlice(const FrameInputs& inputs, uint32_t stage, uint32_t slice,
                                     uint32_t slices) {
    assert(stage < getStageCount(inputs.settings) && slice < slices &&
           slices <= gpu::kMaxComputeSlices);
    const glm::uvec2 sliceParams(slice, slices);
    if (inputs.settings.radiusMode != gpu::kRadiusDensity) {
        if (stage + 1 < getStageCount(inputs.settings))
            sumLightPower(inputs, sliceParams);
        else
            setTravelRadii(inputs, sliceParams);
        return;
    }
    const uint32_t slots =
        std::bit_ceil(std::max(mBuffers.getFrameResults(), 1u) * kSlotsPerPhoton);
    // The table (a slot is 32 bytes), with splat_clip the radius stage's order's counts (one
    // per grid cell, zeroed with the table), the caustic photons' draw command and list (at an
    // offset that suits any storage-buffer alignment up to 32 x slots), the discs' count (a
    // uvec4) and list (at a multiple of kListAlignment), then with splat_clip the order's photon
    // indices.
    const bool ordered = inputs.settings.splatClip;
    const size_t capacity = std::max(mBuffers.getFrameResults(), 1u);
    const size_t countsOffset = size_t(slots) * gpu::kDensitySlotUints * sizeof(uint32_t);
    mCausticOffset = countsOffset + (ordered ? gpu::kOrderCells * sizeof(uint32_t) : 0);
    const size_t causticEnd =
        mCausticOffset + gpu::kSplatDrawUvec4s * sizeof(glm::uvec4) + capacity * sizeof(uint32_t);
    mDiscOffset = (causticEnd + kListAlignment - 1) / kListAlignment * kListAlignment;
    const size_t orderOffset = mDiscOffset + sizeof(glm::uvec4) + capacity * sizeof(uint32_t);
    const size_t cellBytes = orderOffset + (ordered ? capacity * sizeof(uint32_t) : 0);
    // Grows only (a budget that adapts to the frame time moves the layout every few frames); the
    // layout above follows this frame's photons, so a smaller frame clears a smaller table.
    if (cellBytes > mCells.getSize()) mCells = gl::Buffer("photon density cells", cellBytes);
    mOrderOffset = ordered ? orderOffset : 0;
    if (inputs.settings.splatClip) reserveClip();
    if (stage == 0 && slice == 0) {
        // The table and the counts (the caustic list is written before it is read; its command
        // follows).
        mZeroFill.fill(mCells, mCausticOffset);
        const glm::uvec4 draw[gpu::kSplatDrawUvec4s] = {
            {gpu::getSplatIndexCount(inputs.settings.splatShape), 0, 0, 0}, {0, 0, 0, 0}};
        mCells.upload(mCausticOffset, sizeof(draw), draw);
        // The discs' count (the splat's commands are written from it).
        const glm::uvec4 none(0u);
        mCells.upload(mDiscOffset, sizeof(none), &none);
        if (ordered)
            sortPhotons(inputs, countsOffset / sizeof(uint32_t), orderOffset / sizeof(uint32_t));
    }
    const int neighbours = std::max(int(std::lround(float(inputs.settings.splatNeighbours) *
                                                    inputs.progressive.neighbourFactor)),
                                    1);
    const float scale = inputs.getRadiusScale();
    const float radiusMin = inputs.settings.radiusMinM.value_or(0.0f) * scale;
    const float even =
        computeEvenRadius(inputs.scene.getSurfaceArea(), inputs.settings.photons, neighbours);
    const float radiusMax =
        inputs.settings.radiusMaxM.value_or(computeDensityRadiusMax(
            inputs.scene.getSurfaceArea(), inputs.settings.photons, neighbours)) *
        scale;
    const float cell = kFinestCellFraction * even;

    gpu::DensityParams params{};
    params.finestCellM = cell;
    params.neighbours = float(neighbours);
    params.radiusMinM = radiusMin;
    params.radiusMaxM = radiusMax;
    params.radiusScale = scale;
    params.rayOffsetM = inputs.scene.getRayEpsilon();
    params.travelRadiusFactor = inputs.progressive.travelRadiusFactor;
    params.mergeCellPerRadius = inputs.settings.splatMerge;
    constexpr uint32_t kStages[3] = {gpu::kDensityStageCount, gpu::kDensityStageRadius,
                                     gpu::kDensityStageMerge};
    params.stage = kStages[stage];
    params.slotMask = slots - 1;
    params.spreadStrong = inputs.progressive.spreadStrongPhotons ? 1u : 0u;
    params.slice = sliceParams.x;
    params.slices = sliceParams.y;
    params.orderAt = uint32_t(mOrderOffset / sizeof(uint32_t));
    params.causticListAt = uint32_t(mCausticOffset / sizeof(uint32_t));
    params.squash = inputs.settings.squash;
    params.discListAt = uint32_t(mDiscOffset / sizeof(uint32_t));
    mParams.upload(0, sizeof(params), &params);

    mBuffers.bind();
    inputs.scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    mCells.bindBase(gl::BufferTarget::Storage, gpu::kBindingDensityCells);
    if (inputs.settings.splatClip)
        mClip.bindBase(gl::BufferTarget::Storage, gpu::kBindingSplatClip);
    if (measuresSurfaceEnds(params.stage, inputs.settings))
        mViewer.bindTextures(gpu::kUnitGBufferFirst);
    useStage(params.stage, inputs.settings);
    // The block is written anew for every dispatch (the GL orders the update after the
    // dispatch before it that read the last one).
    dispatch(sliceParams);
    // The radius stage reads the counted table; the splat's vertex stage reads the radii and
    // the caustic list, its draw the caustic photons' count.
    gl::memoryBarrier(gl::Barrier::Storage | gl::Barrier::Command);
    if (stage + 1 == getStageCount(inputs.settings) && slice + 1 == slices) {
        // The discs are listed: the splat's draws take them alone.
        gpu::PrepareParams prepare{};
        prepare.stage = gpu::kPrepareStageDiscDraws;
        prepare.splatDraws = inputs.splatDraws;
        mPrepareParams.upload(0, sizeof(prepare), &prepare);
        mPrepareParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
        mCells.bindRange(gl::BufferTarget::Storage, gpu::kBindingDiscList, mDiscOffset,
                         mCells.getSize() - mDiscOffset);
        mDiscDraws.use();
        gl::dispatchCompute(1);
        gl::memoryBarrier(gl::Barrier::Storage | gl::Barrier::Command);
    }
}

} // namespace ispm
