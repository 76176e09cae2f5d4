// PhotonPointsDrawer: one point per photon, its vertex index addressing the storage buffer.
#include "viewer/photon_points.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/gbuffer.h"
#include "render/shader_root.h"

#include <shared/scene_data.h>
#include <shared/viewer_data.h>

#include <algorithm>

namespace ispm {
namespace {

constexpr GLuint kUnitPosition = 0; // shaders/viewer/photon_points.frag
constexpr float kPointSizePx = 2.0f;
constexpr glm::vec4 kBounceTint{1.0f, 0.85f, 0.2f, kPointSizePx}; // yellow: first bounce
constexpr glm::vec4 kResultTint{0.2f, 0.8f, 1.0f, kPointSizePx};  // cyan: stored photons

ReloadableProgram buildPointsProgram(bool isResult) {
    std::vector<std::string> defines;
    if (isResult) defines.emplace_back("RESULT_PHOTONS");
    return ReloadableProgram({.label = isResult ? "viewer result photons" : "viewer bounce photons",
                              .stages = {{gl::ShaderStage::Vertex, "viewer/photon_points.vert"},
                                         {gl::ShaderStage::Fragment, "viewer/photon_points.frag"}},
                              .defines = defines});
}

// Draws `capacity` points; the vertex stage drops those past this frame's count.
void drawPoints(const ReloadableProgram& program, const gl::Buffer& params, const glm::vec4& tint,
                uint32_t capacity) {
    program.use();
    const gpu::PhotonPointsParams block{.tint = tint};
    params.upload(0, sizeof(block), &block);
    params.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::drawArrays(gl::Primitive::Points, 0, static_cast<int>(capacity));
}

} // namespace

PhotonPointsDrawer::PhotonPointsDrawer()
    : mBounceProgram(buildPointsProgram(false)), mResultProgram(buildPointsProgram(true)),
      mBounceParams("viewer bounce points parameters", sizeof(gpu::PhotonPointsParams)),
      mResultParams("viewer result points parameters", sizeof(gpu::PhotonPointsParams)),
      mVertexArray("viewer photon points vao") {}

void PhotonPointsDrawer::draw(const FrameRunner& runner, PhotonPoints which, int width,
                              int height) const {
    const PhotonBuffers& buffers = runner.getPhotonBuffers();
    // No photons this frame (bounces = 0, photons = 0): the buffers may not even exist.
    if (which == PhotonPoints::None || !runner.hasIndirect()) return;
    gl::applyState({.programPointSize = true});
    gl::bindDefaultFramebuffer(width, height);
    runner.getFrameInputs().frameConstants.bindBase(gl::BufferTarget::Uniform,
                                                    gpu::kBindingFrameConstants);
    buffers.bind();
    runner.getViewerGBuffer().getChannel("position").bindUnit(kUnitPosition);
    mVertexArray.bind();
    if (which == PhotonPoints::Bounce || which == PhotonPoints::Both) {
        drawPoints(mBounceProgram, mBounceParams, kBounceTint, buffers.getBounceCapacity());
    }
    if (which == PhotonPoints::Result || which == PhotonPoints::Both) {
        drawPoints(mResultProgram, mResultParams, kResultTint, buffers.getResultCapacity());
    }
}

} // namespace ispm
