// Trace: prepare (GPU count -> dispatch), trace, prepare (results -> splat draws).
#include "render/photon_trace_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"
#include "scene/settings.h"

#include <shared/photon_data.h>
#include <shared/scene_data.h>

namespace ispm {

PhotonTracePass::PhotonTracePass(PhotonBuffers& buffers)
    : mBuffers(buffers),
      mPrepare(ReloadableProgram(
          {.label = "photon prepare",
           .stages = {{gl::ShaderStage::Compute, "photon/photon_prepare.comp"}}})),
      mTrace(
          ReloadableProgram({.label = "photon trace",
                             .stages = {{gl::ShaderStage::Compute, "photon/photon_trace.comp"}}})),
      mPrepareParams("photon prepare parameters", sizeof(gpu::PrepareParams)),
      mTraceParams("photon trace parameters", sizeof(gpu::TraceParams)) {}

void PhotonTracePass::execute(const FrameInputs& inputs) {
    gpu::PrepareParams prepare{};
    prepare.control = glm::uvec4(mBuffers.getResultCapacity(), mBuffers.getBounceCapacity(),
                                 gpu::kPrepareStageBeforeTrace,
                                 static_cast<uint32_t>(inputs.settings.splatPasses));
    mPrepareParams.upload(0, sizeof(prepare), &prepare);
    gpu::TraceParams trace{};
    trace.control = glm::uvec4(static_cast<uint32_t>(inputs.settings.bounces), inputs.seed,
                               inputs.settings.rngGenerator, inputs.settings.rngMode);
    trace.ray = glm::vec4(inputs.scene.getRayEpsilon(), 0.0f, 0.0f, 0.0f);
    mTraceParams.upload(0, sizeof(trace), &trace);

    mBuffers.bind();
    inputs.scene.bind();
    mPrepare.use();
    mPrepareParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::dispatchCompute(1);
    // The dispatch arguments and counters were written by a shader.
    gl::memoryBarrier(gl::Barrier::Command | gl::Barrier::Storage);

    mTrace.use();
    mTraceParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::dispatchComputeIndirect(mBuffers.getCounters(),
                                offsetof(gpu::PhotonCounters, traceDispatch));
    gl::memoryBarrier(gl::Barrier::Storage);

    // The same block again, at its second stage (the GL orders the update after the dispatch
    // that read the first).
    prepare.control.z = gpu::kPrepareStageBeforeSplat;
    mPrepareParams.upload(0, sizeof(prepare), &prepare);
    mPrepare.use();
    mPrepareParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::dispatchCompute(1);
    // Result photons feed the splat vertex stage; draw commands feed glDrawArraysIndirect.
    gl::memoryBarrier(gl::Barrier::Command | gl::Barrier::Storage);
}

} // namespace ispm
