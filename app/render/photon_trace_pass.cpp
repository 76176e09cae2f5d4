// Trace: prepare (GPU count -> dispatch), trace, prepare (results -> splat draws).
#include "render/photon_trace_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"
#include "scene/settings.h"

namespace ispm {
namespace {

// Uniform locations of photon_prepare.comp and photon_trace.comp.
constexpr GLint kLocationCapacity = 0;
constexpr GLint kLocationStage = 1;
constexpr GLint kLocationSplatPasses = 2;
constexpr GLint kLocationParams = 0;
constexpr GLint kLocationEpsilon = 1;
constexpr GLuint kStageBeforeTrace = 0;
constexpr GLuint kStageBeforeSplat = 1;

} // namespace

PhotonTracePass::PhotonTracePass(PhotonBuffers& buffers)
    : mBuffers(buffers),
      mPrepare(ReloadableProgram(
          {.label = "photon prepare",
           .stages = {{gl::ShaderStage::Compute, "photon/photon_prepare.comp"}}})),
      mTrace(
          ReloadableProgram({.label = "photon trace",
                             .stages = {{gl::ShaderStage::Compute, "photon/photon_trace.comp"}}})) {
}

void PhotonTracePass::execute(const FrameInputs& inputs) {
    mBuffers.bind();
    inputs.scene.bind();
    mPrepare.use();
    glUniform2ui(kLocationCapacity, mBuffers.getResultCapacity(), mBuffers.getBounceCapacity());
    glUniform1ui(kLocationStage, kStageBeforeTrace);
    gl::dispatchCompute(1);
    // The dispatch arguments and counters were written by a shader.
    gl::memoryBarrier(gl::Barrier::Command | gl::Barrier::Storage);

    mTrace.use();
    glUniform4ui(kLocationParams, static_cast<GLuint>(inputs.settings.bounces), inputs.seed,
                 inputs.settings.rngGenerator, inputs.settings.rngMode);
    glUniform1f(kLocationEpsilon, inputs.scene.getRayEpsilon());
    gl::dispatchComputeIndirect(mBuffers.getCounters(),
                                offsetof(gpu::PhotonCounters, traceDispatch));
    gl::memoryBarrier(gl::Barrier::Storage);

    mPrepare.use();
    glUniform1ui(kLocationStage, kStageBeforeSplat);
    glUniform1ui(kLocationSplatPasses, static_cast<GLuint>(inputs.settings.splatPasses));
    gl::dispatchCompute(1);
    // Result photons feed the splat vertex stage; draw commands feed glDrawArraysIndirect.
    gl::memoryBarrier(gl::Barrier::Command | gl::Barrier::Storage);
}

} // namespace ispm
