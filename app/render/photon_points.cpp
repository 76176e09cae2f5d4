// PhotonPointsDrawer: one point per photon, its vertex index addressing the storage buffer.
#include "render/photon_points.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/fullscreen.h"
#include "render/gbuffer.h"
#include "render/photon_budget.h"
#include "render/readback.h"
#include "render/shader_root.h"

#include <shared/debug_data.h>
#include <shared/scene_data.h>

#include <algorithm>

namespace ispm {
namespace {

constexpr GLuint kUnitPosition = 0; // shaders/debug/photon_points.frag
constexpr GLuint kUnitDisplay = 0;  // shaders/debug/photon_backdrop.frag
constexpr float kPointSizePx = 2.0f;
constexpr glm::vec4 kBounceTint{1.0f, 0.85f, 0.2f, kPointSizePx}; // yellow: first bounce
constexpr glm::vec4 kResultTint{0.2f, 0.8f, 1.0f, kPointSizePx};  // cyan: stored photons
constexpr float kPowerGamma = 2.2f; // power colours are encoded like the default tone map

ReloadableProgram buildPointsProgram(bool isResult) {
    std::vector<std::string> defines;
    if (isResult) defines.emplace_back("RESULT_PHOTONS");
    return ReloadableProgram({.label = isResult ? "result photon points" : "bounce photon points",
                              .stages = {{gl::ShaderStage::Vertex, "debug/photon_points.vert"},
                                         {gl::ShaderStage::Fragment, "debug/photon_points.frag"}},
                              .defines = defines});
}

// Draws `capacity` points; the vertex stage drops those past this frame's count.
void drawPoints(const ReloadableProgram& program, const gl::Buffer& params, const glm::vec4& tint,
                PhotonColour colour, float powerScale, uint32_t capacity) {
    program.use();
    const gpu::PhotonPointsParams block{.tint = glm::vec3(tint),
                                        .pointSizePx = tint.a,
                                        .powerScale = powerScale,
                                        .inverseGamma = 1.0f / kPowerGamma,
                                        .colouring = static_cast<uint32_t>(colour)};
    params.upload(0, sizeof(block), &block);
    params.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::drawArrays(gl::Primitive::Points, 0, static_cast<int>(capacity));
}

} // namespace

std::optional<PhotonAov> findPhotonAov(const std::string& name) {
    const auto split = name.find('_');
    if (split == std::string::npos) return std::nullopt;
    const std::string buffer = name.substr(0, split);
    const std::string colour = name.substr(split + 1);
    PhotonAov aov;
    if (buffer == "bounce") {
        aov.points = PhotonPoints::Bounce;
    } else if (buffer == "result") {
        aov.points = PhotonPoints::Result;
    } else {
        return std::nullopt;
    }
    if (colour == "direction") {
        aov.colour = PhotonColour::Direction;
    } else if (colour == "power") {
        aov.colour = PhotonColour::Power;
    } else {
        return std::nullopt;
    }
    return aov;
}

double computePhotonPowerScale(const FrameRunner& runner) {
    const GpuScene& scene = runner.getPasses().scene;
    const std::vector<Light>& lights = runner.getPasses().model.lights;
    double power = 0.0;
    for (size_t i = 0; i < lights.size(); ++i) {
        power += computeLightViewPower(lights[i], scene.getLightCameras(), uint32_t(i),
                                       scene.getLightResolution());
    }
    const uint32_t photons = countPhotons(runner.getPasses().emit.getGrids());
    return power > 0.0 && photons > 0 ? double(photons) / power : 0.0;
}

PhotonPointsDrawer::PhotonPointsDrawer()
    : mBounceProgram(buildPointsProgram(false)), mResultProgram(buildPointsProgram(true)),
      mBackdropProgram({.label = "photon points backdrop",
                        .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                   {gl::ShaderStage::Fragment, "debug/photon_backdrop.frag"}}}),
      mBounceParams("bounce points parameters", sizeof(gpu::PhotonPointsParams)),
      mResultParams("result points parameters", sizeof(gpu::PhotonPointsParams)),
      mVertexArray("photon points vao") {}

void PhotonPointsDrawer::draw(const FrameRunner& runner, PhotonPoints which,
                              PhotonColour colour) const {
    const PhotonBuffers& buffers = runner.getPasses().photons;
    // No photons this frame (bounces = 0, photons = 0): the buffers may not even exist.
    if (which == PhotonPoints::None || !runner.getFrameSettings().hasIndirect()) return;
    gl::applyState({.programPointSize = true});
    runner.getFrameInputs().frameConstants.bindBase(gl::BufferTarget::Uniform,
                                                    gpu::kBindingFrameConstants);
    buffers.bind();
    runner.getPasses().gbuffer.getGBuffer().getChannel("position").bindUnit(kUnitPosition);
    mVertexArray.bind();
    const auto powerScale =
        colour == PhotonColour::Power
            ? static_cast<float>(computePhotonPowerScale(runner) / kPhotonPowerWhite)
            : 0.0f;
    if (which == PhotonPoints::Bounce || which == PhotonPoints::Both) {
        drawPoints(mBounceProgram, mBounceParams, kBounceTint, colour, powerScale,
                   buffers.getBounceCapacity());
    }
    if (which == PhotonPoints::Result || which == PhotonPoints::Both) {
        drawPoints(mResultProgram, mResultParams, kResultTint, colour, powerScale,
                   buffers.getResultCapacity());
    }
}

Image PhotonPointsDrawer::renderAov(const FrameRunner& runner, const PhotonAov& aov,
                                    bool backdrop) const {
    ColorTarget target("photon points image", gl::Format::RGBA8);
    target.resize(runner.getFrameSettings().width, runner.getFrameSettings().height);
    target.bind();
    gl::applyState({});
    if (backdrop) {
        mBackdropProgram.use();
        runner.getAov(Aov::Display).bindUnit(kUnitDisplay);
        mVertexArray.bind();
        drawFullscreenTriangle();
    } else {
        target.clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    draw(runner, aov.points, aov.colour);
    return readTextureImage(target.getTexture());
}

} // namespace ispm
