// Reference path and light tracing: setup and one sample per dispatch (two for light tracing:
// trace and splat, then resolve into the accumulation image).
#include "render/reference_pass.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/frame_constants.h"
#include "render/gbuffer.h"
#include "render/readback.h"
#include "render/shader_root.h"

#include <shared/light_trace_data.h>
#include <shared/scene_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

constexpr GLuint kImageUnitAccumulation = 0;
constexpr unsigned kGroupSize = 8;       // local_size_x/y of reference.comp, light_resolve.comp
constexpr unsigned kLightGroupSize = 64; // local_size_x of light_trace.comp
constexpr size_t kSplatFloatsPerPixel = 3;
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
      mFrameConstants("reference frame constants", sizeof(gpu::FrameConstants)),
      mParams("reference parameters",
              std::max(sizeof(gpu::ReferenceParams), sizeof(gpu::LightTraceParams))),
      mWidth(settings.width), mHeight(settings.height),
      mBounces(settings.bouncesSet ? settings.bounces : kReferenceDefaultBounces),
      mSeed(settings.seed), mMethod(settings.referenceMethod) {
    std::vector<std::string> defines = getGBufferDefines();
    const std::vector<std::string> rays = mGpuScene.getRayDefines();
    defines.insert(defines.end(), rays.begin(), rays.end());
    if (mMethod == gpu::kReferenceLight) {
        mProgram = gl::Program::build(
            getShaderRoot(), {.label = "reference light tracer",
                              .stages = {{gl::ShaderStage::Compute, "reference/light_trace.comp"}},
                              .defines = defines});
        mResolveProgram = gl::Program::build(
            getShaderRoot(),
            {.label = "reference light resolve",
             .stages = {{gl::ShaderStage::Compute, "reference/light_resolve.comp"}},
             .defines = defines});
        mSplat = gl::Buffer("reference light splat", static_cast<size_t>(mWidth) *
                                                         static_cast<size_t>(mHeight) *
                                                         kSplatFloatsPerPixel * sizeof(float));
        // The image plane 1 m from the eye spans 2 tan(fovY / 2) by aspect times that.
        const float tanHalf = std::tan(glm::radians(scene.camera.fovYDeg) * 0.5f);
        const float aspect = static_cast<float>(mWidth) / static_cast<float>(mHeight);
        mPixelAreaM2 = 4.0f * tanHalf * tanHalf * aspect /
                       (static_cast<float>(mWidth) * static_cast<float>(mHeight));
    } else {
        mProgram = gl::Program::build(
            getShaderRoot(), {.label = "reference path tracer",
                              .stages = {{gl::ShaderStage::Compute, "reference/reference.comp"}},
                              .defines = defines});
    }
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
    if (mMethod == gpu::kReferenceLight) {
        addLightSample();
    } else {
        addPathSample();
    }
    ++mSamples;
}

void ReferencePass::addPathSample() {
    mProgram.use();
    gpu::ReferenceParams params{};
    params.sampleIndex = static_cast<uint32_t>(mSamples);
    params.bounces = static_cast<uint32_t>(mBounces);
    params.seed = mSeed;
    params.rayOffsetM = mGpuScene.getRayEpsilon();
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::dispatchCompute((static_cast<unsigned>(mWidth) + kGroupSize - 1) / kGroupSize,
                        (static_cast<unsigned>(mHeight) + kGroupSize - 1) / kGroupSize);
    // The next sample reads what this one wrote; read-back follows the same rule.
    gl::memoryBarrier(gl::Barrier::ImageAccess | gl::Barrier::TextureUpdate);
}

void ReferencePass::addLightSample() {
    // One light path per pixel: the same work per sample as a camera path, spread by the lights.
    const auto pathCount = static_cast<uint32_t>(mWidth) * static_cast<uint32_t>(mHeight);
    gpu::LightTraceParams params{};
    params.sampleIndex = static_cast<uint32_t>(mSamples);
    params.bounces = static_cast<uint32_t>(mBounces);
    params.seed = mSeed;
    params.pathCount = pathCount;
    params.rayFloorM = mGpuScene.getRayEpsilon();
    params.pixelAreaM2 = mPixelAreaM2;
    params.cameraAxisW = glm::normalize(mScene.camera.target - mScene.camera.position);
    const Aabb& bounds = mGpuScene.getBounds();
    params.sceneCentreW = bounds.getCenter();
    params.sceneRadiusM = 0.5f * glm::length(bounds.getExtent());
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    mSplat.bindBase(gl::BufferTarget::Storage, gpu::kBindingLightSplat);
    mProgram.use();
    gl::dispatchCompute((pathCount + kLightGroupSize - 1) / kLightGroupSize);
    // The resolve reads the splats; then the next sample's splats follow its clearing.
    gl::memoryBarrier(gl::Barrier::Storage);
    mResolveProgram.use();
    gl::dispatchCompute((static_cast<unsigned>(mWidth) + kGroupSize - 1) / kGroupSize,
                        (static_cast<unsigned>(mHeight) + kGroupSize - 1) / kGroupSize);
    gl::memoryBarrier(gl::Barrier::ImageAccess | gl::Barrier::TextureUpdate | gl::Barrier::Storage);
}

Image ReferencePass::readMean() const {
    Image image = readTextureImage(mAccumulation);
    const float scale = mSamples > 0 ? 1.0f / static_cast<float>(mSamples) : 0.0f;
    for (glm::vec3& p : image.pixels)
        p *= scale;
    return image;
}

} // namespace ispm
