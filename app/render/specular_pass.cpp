// SpecularPass: a compute pass over the viewer G-buffer (specular/specular_trace.comp).
#include "render/specular_pass.h"

#include "gl/state.h"
#include "render/gpu_scene.h"

#include <shared/scene_data.h>
#include <shared/specular_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// Image unit 0: uSpecularLight in specular_trace.comp, uTotal in specular_filter.comp.
constexpr GLuint kImageUnit = 0;
// A hit reprojected onto a visible pixel counts as that pixel's point when their distances from
// the eye differ by less than this share: G-buffer positions are exact to float rounding, and
// the pixel's point lies up to half a pixel's footprint off the hit.
constexpr float kReprojectionDepthTolerance = 0.02f;

// The angle one pixel spans at the eye across the image's middle (the glossy rays' spread is
// measured in it): two points a pixel apart vertically, unprojected at mid depth.
float computePixelAngle(const FrameInputs& inputs) {
    // In double: the two directions' cosine lies within 1e-5 of 1, where float's acos errs by a
    // few percent (and GLSL's, on llvmpipe, by more).
    const glm::dmat4 worldFromClip = glm::inverse(glm::dmat4(inputs.clipFromWorld));
    const auto unproject = [&](double ndcY) {
        const glm::dvec4 p = worldFromClip * glm::dvec4(0.0, ndcY, 0.5, 1.0);
        return glm::normalize(glm::dvec3(p) / p.w - glm::dvec3(inputs.cameraPosition));
    };
    const glm::dvec3 a = unproject(0.0);
    const glm::dvec3 b = unproject(2.0 / double(inputs.height));
    // atan2 of the cross and dot products: exact for small angles, where acos is not.
    return static_cast<float>(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

} // namespace

SpecularPass::SpecularPass(const GBuffer& viewer, const gl::Texture& indirect,
                           const gl::Texture& total)
    : mViewer(viewer), mIndirect(indirect), mTotal(total),
      mAmbientProgram(ReloadableProgram(
          {.label = "specular ambient",
           .stages = {{gl::ShaderStage::Compute, "specular/specular_ambient.comp"}},
           .defines = getGBufferDefines()})),
      mProgram({.label = "specular trace",
                .stages = {{gl::ShaderStage::Compute, "specular/specular_trace.comp"}},
                .defines = getGBufferDefines()}),
      mFilter(ReloadableProgram(
          {.label = "specular filter",
           .stages = {{gl::ShaderStage::Compute, "specular/specular_filter.comp"}},
           .defines = getGBufferDefines()})),
      mParams("specular parameters", sizeof(gpu::SpecularParams)),
      mAmbient(gl::Texture::create2D("specular ambient", gl::Format::RGBA32F, 1, 1)) {}

bool SpecularPass::isOn(const FrameSettings& settings, const GpuScene& scene) {
    return settings.specularDepth > 0 && settings.bounces > 0 && scene.hasTracedSpecular();
}

void SpecularPass::execute(const FrameInputs& inputs) {
    const FrameSettings& settings = inputs.settings;
    if (!isOn(settings, inputs.scene)) return;
    gpu::SpecularParams params{};
    // Light seen in a mirror reflected once more than the mirror's own: `bounces` caps the
    // levels as it caps the reference's camera paths.
    params.levels = static_cast<uint32_t>(std::min(settings.specularDepth, settings.bounces));
    params.rayFloorM = inputs.scene.getRayEpsilon();
    params.reprojectionTolerance = kReprojectionDepthTolerance;
    params.pixelAngleRad = computePixelAngle(inputs);
    mParams.upload(0, sizeof(params), &params);
    inputs.scene.bind();
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mIndirect.bindUnit(gpu::kUnitIndirect);
    if (mLight.getWidth() != inputs.width || mLight.getHeight() != inputs.height) {
        mLight = gl::Texture::create2D("specular light", gl::Format::RGBA32F, inputs.width,
                                       inputs.height);
    }
    // One work group samples the view for the ambient estimate, once for every traced pixel.
    mAmbient.bindImage(gpu::kSpecularAmbientImage, false, true);
    mAmbientProgram.use();
    gl::dispatchCompute(1, 1);
    gl::memoryBarrier(gl::Barrier::ImageAccess);
    mAmbient.bindImage(gpu::kSpecularAmbientImage, true, false);
    mLight.bindImage(kImageUnit, false, true);
    mProgram.get(inputs.scene.getRayDefines()).use();
    const auto groups = [](int size) {
        return (static_cast<unsigned>(size) + gpu::kSpecularGroupSize - 1) /
               gpu::kSpecularGroupSize;
    };
    gl::dispatchCompute(groups(inputs.width), groups(inputs.height));
    gl::memoryBarrier(gl::Barrier::TextureFetch);
    mLight.bindUnit(gpu::kUnitFilterSource);
    mTotal.bindImage(kImageUnit, true, true);
    mFilter.use();
    gl::dispatchCompute(groups(inputs.width), groups(inputs.height));
    // The post passes and the tone map sample the image written here.
    gl::memoryBarrier(gl::Barrier::TextureFetch | gl::Barrier::ImageAccess);
}

} // namespace ispm
