// Trace: prepare (GPU count -> dispatch), trace, prepare (results -> splat draws).
#include "render/photon_trace_pass.h"

#include "gl/context.h"
#include "gl/gl.h"
#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"
#include "settings/settings.h"

#include <shared/photon_data.h>
#include <shared/scene_data.h>

#include <cassert>

namespace ispm {

PhotonTracePass::PhotonTracePass(PhotonBuffers& buffers)
    : mBuffers(buffers),
      mPrepare(ReloadableProgram(
          {.label = "photon prepare",
           .stages = {{gl::ShaderStage::Compute, "photon/photon_prepare.comp"}}})),
      mTrace({.label = "photon trace",
              .stages = {{gl::ShaderStage::Compute, "photon/photon_trace.comp"}}}),
      mPrepareParams("photon prepare parameters", sizeof(gpu::PrepareParams)),
      mTraceParams("photon trace parameters", sizeof(gpu::TraceParams)),
      mPhotonsPerLane(gl::isCurrentRendererSoftware() ? gpu::kTracePhotonsPerLaneSoftware : 1u) {}

void PhotonTracePass::execute(const FrameInputs& inputs) {
    executeSlice(inputs, 0, 1);
}

void PhotonTracePass::executeSlice(const FrameInputs& inputs, uint32_t slice, uint32_t slices) {
    assert(slice < slices && slices <= gpu::kMaxComputeSlices);
    gpu::PrepareParams prepare{};
    prepare.resultCapacity = mBuffers.getResultCapacity();
    prepare.bounceCapacity = mBuffers.getBounceCapacity();
    prepare.stage = gpu::kPrepareStageBeforeTrace;
    prepare.splatDraws = inputs.splatDraws;
    prepare.splatIndexCount = gpu::getSplatIndexCount(inputs.settings.splatShape);
    prepare.photonsPerLane = mPhotonsPerLane;
    gpu::TraceParams trace{};
    trace.bounces = static_cast<uint32_t>(inputs.settings.bounces);
    trace.seed = inputs.seed;
    trace.rngGenerator = inputs.settings.rngGenerator;
    trace.rngMode = inputs.settings.rngMode;
    trace.rayOffsetM = inputs.scene.getRayEpsilon();
    trace.slice = slice;
    trace.slices = slices;
    mTraceParams.upload(0, sizeof(trace), &trace);

    mBuffers.bind();
    inputs.scene.bind();
    if (slice == 0) {
        mPrepareParams.upload(0, sizeof(prepare), &prepare);
        mPrepare.use();
        mPrepareParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
        gl::dispatchCompute(1);
        // The dispatch arguments and counters were written by a shader.
        gl::memoryBarrier(gl::Barrier::Command | gl::Barrier::Storage);
    }

    mTrace.get(inputs.scene.getRayDefines()).use();
    mTraceParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    if (slices == 1) {
        gl::dispatchComputeIndirect(mBuffers.getCounters(),
                                    offsetof(gpu::PhotonCounters, traceDispatch));
    } else {
        mBuffers.dispatchSlice(offsetof(gpu::PhotonCounters, bounce), slice, slices,
                               mPhotonsPerLane);
    }
    gl::memoryBarrier(gl::Barrier::Storage);
    if (slice + 1 < slices) return;

    // The same block again, at its second stage (the GL orders the update after the dispatch
    // that read the first).
    prepare.stage = gpu::kPrepareStageBeforeSplat;
    mPrepareParams.upload(0, sizeof(prepare), &prepare);
    mPrepare.use();
    mPrepareParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::dispatchCompute(1);
    // Result photons feed the splat vertex stage; draw commands feed glDrawArraysIndirect.
    gl::memoryBarrier(gl::Barrier::Command | gl::Barrier::Storage);
}

} // namespace ispm
