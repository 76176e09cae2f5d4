// Reference path tracing: setup and one sample per dispatch.
#include "render/reference_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/frame_constants.h"
#include "render/gbuffer.h"
#include "render/readback.h"
#include "render/shader_root.h"

#include <shared/scene_data.h>

namespace ispm {
namespace {

constexpr GLuint kImageUnitAccumulation = 0;
constexpr unsigned kGroupSize = 8; // local_size_x/y of reference.comp
// The light G-buffer of the photon mapper is not used here; the GPU scene still derives light
// cameras, at the smallest size.
constexpr int kUnusedLightResolution = 1;

} // namespace

ReferencePass::ReferencePass(const Scene& scene, const Settings& settings)
    : ReferencePass(scene, std::make_unique<GpuScene>(scene, kUnusedLightResolution), nullptr,
                    resolveFrameSettings(settings)) {}

ReferencePass::ReferencePass(const Scene& scene, const GpuScene& gpuScene, const Settings& settings)
    : ReferencePass(scene, nullptr, &gpuScene, resolveFrameSettings(settings)) {}

ReferencePass::ReferencePass(const Scene& scene, std::unique_ptr<GpuScene> owned,
                             const GpuScene* borrowed, const FrameSettings& settings)
    : mScene(scene), mOwnedScene(std::move(owned)), mGpuScene(borrowed ? *borrowed : *mOwnedScene),
      mProgram(gl::Program::build(
          getShaderRoot(), {.label = "reference path tracer",
                            .stages = {{gl::ShaderStage::Compute, "reference/reference.comp"}},
                            .defines = getGBufferDefines()})),
      mFrameConstants("reference frame constants", sizeof(gpu::FrameConstants)),
      mParams("reference parameters", sizeof(gpu::ReferenceParams)), mWidth(settings.width),
      mHeight(settings.height),
      mBounces(settings.bouncesSet ? settings.bounces : kReferenceDefaultBounces),
      mSeed(settings.seed) {
    mAccumulation =
        gl::Texture::create2D("reference accumulation", gl::Format::RGBA32F, mWidth, mHeight);
    mAccumulation.clear(glm::vec4(0.0f));
    const gpu::FrameConstants fc =
        computeFrameConstants(scene, mGpuScene, settings, mWidth, mHeight, settings.seed);
    mFrameConstants.upload(0, sizeof(fc), &fc);
}

void ReferencePass::addSample() {
    mGpuScene.bind();
    mFrameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mAccumulation.bindImage(kImageUnitAccumulation, true, true);
    mProgram.use();
    gpu::ReferenceParams params{};
    params.control =
        glm::uvec4(static_cast<uint32_t>(mSamples), static_cast<uint32_t>(mBounces), mSeed, 0u);
    params.ray = glm::vec4(mGpuScene.getRayEpsilon(), 0.0f, 0.0f, 0.0f);
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::dispatchCompute((static_cast<unsigned>(mWidth) + kGroupSize - 1) / kGroupSize,
                        (static_cast<unsigned>(mHeight) + kGroupSize - 1) / kGroupSize);
    // The next sample reads what this one wrote; read-back follows the same rule.
    gl::memoryBarrier(gl::Barrier::ImageAccess | gl::Barrier::TextureUpdate);
    ++mSamples;
}

Image ReferencePass::readMean() const {
    Image image = readTextureImage(mAccumulation);
    const float scale = mSamples > 0 ? 1.0f / static_cast<float>(mSamples) : 0.0f;
    for (glm::vec3& p : image.pixels)
        p *= scale;
    return image;
}

} // namespace ispm
