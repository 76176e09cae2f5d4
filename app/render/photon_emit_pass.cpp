// Emission: one transform-feedback capture over every light view's grid.
#include "render/photon_emit_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"
#include "settings/settings.h"

#include <shared/importance_data.h>
#include <shared/scene_data.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

namespace ispm {
namespace {

constexpr uint64_t kMaxResultPhotons = uint64_t(1) << 23; // 64 bytes each

// Uniform locations of shaders/photon/photon_emit.geom.

} // namespace

PhotonEmitPass::PhotonEmitPass(const GBuffer& lightGBuffer, const gl::Buffer& importanceCdf,
                               PhotonBuffers& buffers)
    : mLightGBuffer(lightGBuffer), mImportanceCdf(importanceCdf), mBuffers(buffers),
      mProgram(ReloadableProgram(
          {.label = "photon emit",
           .stages = {{gl::ShaderStage::Vertex, "photon/photon_emit.vert"},
                      {gl::ShaderStage::Geometry, "photon/photon_emit.geom"}},
           .defines = getGBufferDefines(),
           .feedbackVaryings = {"outPositionDistance", "outDirectionDensity", "outPower"}})),
      mEmitterProgram(
          ReloadableProgram({.label = "photon emit from emitters",
                             .stages = {{gl::ShaderStage::Compute, "photon/emitter_emit.comp"}}})),
      mEnvironmentProgram(ReloadableProgram(
          {.label = "photon emit from the environment",
           .stages = {{gl::ShaderStage::Compute, "photon/environment_emit.comp"}}})),
      mVertexArray("photon emit vao"), mFramebuffer("photon emit (no attachments)"),
      mFeedback("photon emit feedback"),
      mWritten("bounce photons written", gl::QueryTarget::PrimitivesWritten) {
    // Transform feedback with rasterizer discard still needs a complete framebuffer.
    mFramebuffer.setDefaultSize(1, 1);
}

void PhotonEmitPass::execute(const FrameInputs& inputs) {
    const GpuScene& scene = inputs.scene;
    mGrids = computeEmissionGrids(inputs.model, scene.getLightCameras(), scene.getLightResolution(),
                                  static_cast<uint32_t>(inputs.settings.photons),
                                  scene.getEmitters(), scene.getEnvironmentPowerW());
    const uint32_t photons = countPhotons(mGrids);
    const auto bounces = static_cast<uint32_t>(inputs.settings.bounces);
    // Every photon may store a result at every bounce, but most are absorbed or leave first: the
    // result buffer holds at most kMaxResultPhotons (512 MiB); appends past it are counted as
    // overflow, which render and bench print.
    const uint64_t results = std::min<uint64_t>(uint64_t(photons) * bounces, kMaxResultPhotons);
    mBuffers.reserve(std::max(photons, 1u), std::max(uint32_t(results), 1u));
    std::vector<glm::uvec4> gridTable;
    mGridLights.clear();
    for (const EmissionGrid& g : mGrids) {
        const uint32_t light = g.isEmitterGroup() ? scene.getLightCount() + g.emitterGroup
                               : g.isEnvironment()
                                   ? scene.getPhotonSourceCount() - 1u
                                   : scene.getLightCameras()[g.viewIndex].lightIndex;
        gridTable.emplace_back(g.firstPhoton, g.viewIndex, light, 0u);
        mGridLights.push_back(light);
    }
    mLightCount = scene.getPhotonSourceCount();
    mBuffers.startFrame(gridTable, mLightCount);
    mBuffers.bindLightCounters();

    mFramebuffer.bind();
    mVertexArray.bind();
    mProgram.use();
    gl::applyState({.rasterizerDiscard = true});
    scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mLightGBuffer.bindTextures(gpu::kUnitLightGBufferFirst);
    mImportanceCdf.bindBase(gl::BufferTarget::Storage, gpu::kBindingImportanceCdf);
    std::vector<gpu::EmitParams> params(mGrids.size());
    for (size_t i = 0; i < mGrids.size(); ++i) {
        const EmissionGrid& g = mGrids[i];
        params[i].lightView = g.viewIndex;
        params[i].firstPhoton = g.firstPhoton;
        params[i].gridPhotons = glm::uvec2(g.width, g.height);
        params[i].seed = inputs.seed;
        params[i].rngGenerator = inputs.settings.rngGenerator;
        params[i].lightResolutionPx = uint32_t(scene.getLightResolution());
        params[i].firstBounce = inputs.settings.firstBounce;
    }
    mParams.upload(params);
    mFeedback.attachBuffer(0, mBuffers.getBounce(), 0, mBuffers.getBounce().getSize());
    mWritten.begin();
    mFeedback.begin(gl::Primitive::Points);
    for (size_t i = 0; i < mGrids.size(); ++i) {
        if (mGrids[i].isEmitterGroup() || mGrids[i].isEnvironment()) continue;
        mParams.bind(i);
        gl::drawArrays(gl::Primitive::Points, 0, static_cast<int>(mGrids[i].getCount()));
    }
    mFeedback.end();
    mWritten.end();
    gl::applyState({});
    // The count stays on the GPU: the query result lands in the counters block.
    mWritten.writeResultTo(mBuffers.getCounters(), offsetof(gpu::PhotonCounters, bounce));
    emitFromSurfacesAndSky(inputs);
}

void PhotonEmitPass::emitFromSurfacesAndSky(const FrameInputs& inputs) {
    const GpuScene& scene = inputs.scene;
    const Emitters& emitters = scene.getEmitters();
    std::vector<gpu::EmitterEmitParams> params;
    for (const EmissionGrid& g : mGrids) {
        if (!g.isEmitterGroup()) continue;
        const EmitterGroup& group = emitters.groups[g.emitterGroup];
        gpu::EmitterEmitParams p{};
        p.firstEmitter = group.first;
        p.emitterCount = group.count;
        p.firstPhoton = g.firstPhoton;
        p.photons = g.getCount();
        p.light = scene.getLightCount() + g.emitterGroup;
        p.seed = inputs.seed;
        p.rngGenerator = inputs.settings.rngGenerator == gpu::kRngSobol
                             ? gpu::kRngPcg
                             : inputs.settings.rngGenerator;
        p.firstBounce = inputs.settings.firstBounce;
        p.rayOffsetM = scene.getRayEpsilon();
        p.groupWeight = float(group.weight);
        p.bounceCapacity = uint32_t(mBuffers.getBounce().getSize() / sizeof(gpu::BouncePhoton));
        params.push_back(p);
    }
    const auto environment = std::find_if(mGrids.begin(), mGrids.end(),
                                          [](const EmissionGrid& g) { return g.isEnvironment(); });
    if (params.empty() && environment == mGrids.end()) return;
    // The transform feedback's count is in the counters block: these photons add to it.
    gl::memoryBarrier(gl::Barrier::QueryBuffer | gl::Barrier::TransformFeedback);
    mBuffers.bind();
    scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    if (!params.empty()) {
        mEmitterParams.upload(params);
        mEmitterProgram.use();
        for (size_t i = 0; i < params.size(); ++i) {
            mEmitterParams.bind(i);
            gl::dispatchCompute((params[i].photons + gpu::kEmitterEmitGroupSize - 1) /
                                gpu::kEmitterEmitGroupSize);
        }
    }
    if (environment != mGrids.end()) {
        gpu::EnvironmentEmitParams p{};
        p.sceneMinW = scene.getBounds().lo;
        p.sceneExtentM = scene.getBounds().getExtent();
        p.firstPhoton = environment->firstPhoton;
        p.photons = environment->getCount();
        p.light = scene.getPhotonSourceCount() - 1u;
        p.seed = inputs.seed;
        p.rngGenerator = inputs.settings.rngGenerator == gpu::kRngLcg ? gpu::kRngLcg : gpu::kRngPcg;
        p.firstBounce = inputs.settings.firstBounce;
        p.bounceCapacity = uint32_t(mBuffers.getBounce().getSize() / sizeof(gpu::BouncePhoton));
        p.rayOffsetM = scene.getRayEpsilon();
        mEnvironmentParams.upload(std::span(&p, 1));
        mEnvironmentProgram.use();
        mEnvironmentParams.bind(0);
        gl::dispatchCompute((p.photons + gpu::kEnvironmentEmitGroupSize - 1) /
                            gpu::kEnvironmentEmitGroupSize);
    }
    gl::memoryBarrier(gl::Barrier::Storage);
}

std::vector<uint32_t> PhotonEmitPass::getEmittedPerLight() const {
    std::vector<uint32_t> emitted(mLightCount, 0u);
    for (size_t i = 0; i < mGrids.size(); ++i)
        emitted[mGridLights[i]] += mGrids[i].getCount();
    return emitted;
}

} // namespace ispm
