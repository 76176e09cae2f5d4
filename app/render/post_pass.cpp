// Motion blur, depth blur and bloom: the post passes between compose and tone map.
#include "render/post_pass.h"

#include "gl/state.h"
#include "scene/scene.h"

#include <shared/scene_data.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace ispm {
namespace {

constexpr size_t kScatterChannels = 3; // rgb floats a pixel in the motion-blur buffer

unsigned countGroups(int size) {
    return (static_cast<unsigned>(size) + gpu::kPostGroupSize - 1) / gpu::kPostGroupSize;
}

} // namespace

gpu::PostParams computePostParams(const FrameInputs& inputs) {
    const FrameSettings& s = inputs.settings;
    const Camera& camera = inputs.model.camera;
    gpu::PostParams p{};
    const float sigma = s.bloomRadiusPx / gpu::kBloomSigmasPerRadius;
    p.bloomThreshold = s.bloomThreshold;
    p.bloomIntensity = s.bloomIntensity;
    p.bloomRadiusPx = s.bloomRadiusPx;
    p.bloomSigmaPx = sigma;
    // Pixels per radian at the image centre: the image height spans 2 tan(fovY / 2) on a plane
    // one metre ahead.
    const float halfFov = 0.5f * glm::radians(camera.fovYDeg);
    const float pixelsPerRadian = float(inputs.height) / (2.0f * std::tan(halfFov));
    const float inverseFocus = s.dofFocusM ? 1.0f / *s.dofFocusM : 0.0f;
    p.apertureM = s.dofApertureM;
    p.inverseFocusPerM = inverseFocus;
    p.pixelsPerRadian = pixelsPerRadian;
    p.focusAtCentre = s.dofFocusM ? 0u : 1u;
    p.shutter = s.motionBlurShutter;
    const glm::vec3 axis = camera.target - camera.position;
    const float length = glm::length(axis);
    p.viewAxisW = length > 0.0f ? axis / length : glm::vec3(0.0f, 0.0f, -1.0f);
    return p;
}

PostStep::PostStep(const std::string& label, const std::string& fragmentPath)
    : target(label, gl::Format::RGBA32F),
      program(ReloadableProgram({.label = label,
                                 .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                            {gl::ShaderStage::Fragment, fragmentPath}},
                                 .defines = getGBufferDefines()})),
      vertexArray(label + " vao") {}

size_t PostStep::getGpuBytes() const {
    constexpr size_t kBytesRgba32F = 16;
    const gl::Texture& t = target.getTexture();
    return size_t(t.getWidth()) * size_t(t.getHeight()) * kBytesRgba32F;
}

void PostStep::draw() const {
    target.bind();
    gl::applyState({});
    program.use();
    vertexArray.bind();
    drawFullscreenTriangle();
}

MotionBlurPass::MotionBlurPass(const GBuffer& viewer)
    : mViewer(viewer), mScatter(ReloadableProgram(
                           {.label = "motion blur scatter",
                            .stages = {{gl::ShaderStage::Compute, "post/motion_scatter.comp"}},
                            .defines = getGBufferDefines()})),
      mParams("motion blur parameters"), mResolve("motion blur", "post/motion_resolve.frag") {}

void MotionBlurPass::execute(const FrameInputs& inputs) {
    // Made on first use (memory only while the effect is on); no-ops at the same size.
    mResolve.target.resize(inputs.width, inputs.height);
    const size_t bytes =
        size_t(inputs.width) * size_t(inputs.height) * kScatterChannels * sizeof(float);
    if (mScattered.getSize() != bytes) mScattered = gl::Buffer("motion blur scatter", bytes);
    const std::array<gpu::PostParams, 1> params = {computePostParams(inputs)};
    mParams.upload(params);
    mParams.bind(0);
    mInput->bindUnit(gpu::kUnitPostSource);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mScattered.clearToZero();
    mScattered.bindBase(gl::BufferTarget::Storage, gpu::kBindingPostScatter);
    mScatter.use();
    gl::dispatchCompute(countGroups(inputs.width), countGroups(inputs.height));
    gl::memoryBarrier(gl::Barrier::Storage);
    mResolve.draw();
}

void MotionBlurPass::reloadPrograms(ShaderReloadReport& report) {
    mScatter.reloadIfChanged(report);
    mResolve.program.reloadIfChanged(report);
}

DepthBlurPass::DepthBlurPass(const GBuffer& viewer)
    : mViewer(viewer), mCocMax("depth blur largest radius", sizeof(uint32_t)),
      mParams("depth blur parameters"), mCoc("depth blur coc", "post/dof_coc.frag"),
      mGather("depth blur", "post/dof_gather.frag") {}

void DepthBlurPass::execute(const FrameInputs& inputs) {
    mCoc.target.resize(inputs.width, inputs.height);
    mGather.target.resize(inputs.width, inputs.height);
    const std::array<gpu::PostParams, 1> params = {computePostParams(inputs)};
    mParams.upload(params);
    mParams.bind(0);
    inputs.frameConstants.bindBase(gl::BufferTarget::Uniform, gpu::kBindingFrameConstants);
    mInput->bindUnit(gpu::kUnitPostSource);
    mViewer.bindTextures(gpu::kUnitGBufferFirst);
    mCocMax.clearToZero();
    mCocMax.bindBase(gl::BufferTarget::Storage, gpu::kBindingPostCocMax);
    mCoc.draw();
    // The gather reads the radius bound the coc step's atomics wrote, and its texels.
    gl::memoryBarrier(gl::Barrier::Storage);
    mCoc.target.getTexture().bindUnit(gpu::kUnitPostAux);
    mGather.draw();
}

void DepthBlurPass::reloadPrograms(ShaderReloadReport& report) {
    mCoc.program.reloadIfChanged(report);
    mGather.program.reloadIfChanged(report);
}

BloomPass::BloomPass()
    : mParams("bloom parameters"), mExtract("bloom extract", "post/bloom_extract.frag"),
      mBlurX("bloom blur x", "post/bloom_blur.frag"), mCombine("bloom", "post/bloom_blur.frag") {}

void BloomPass::execute(const FrameInputs& inputs) {
    mExtract.target.resize(inputs.width, inputs.height);
    mBlurX.target.resize(inputs.width, inputs.height);
    mCombine.target.resize(inputs.width, inputs.height);
    std::array<gpu::PostParams, 2> params = {computePostParams(inputs), computePostParams(inputs)};
    params[0].blurAxis = 0u; // along x: extract -> blurred x
    params[0].addsSource = 0u;
    params[1].blurAxis = 1u; // along y, then source - extract + blurred
    params[1].addsSource = 1u;
    mParams.upload(params);
    mParams.bind(0);
    mInput->bindUnit(gpu::kUnitPostSource);
    mExtract.draw();
    mExtract.target.getTexture().bindUnit(gpu::kUnitPostAux);
    mExtract.target.getTexture().bindUnit(gpu::kUnitPostAux2);
    mBlurX.draw();
    mParams.bind(1);
    mBlurX.target.getTexture().bindUnit(gpu::kUnitPostAux);
    mCombine.draw();
}

void BloomPass::reloadPrograms(ShaderReloadReport& report) {
    mExtract.program.reloadIfChanged(report);
    mBlurX.program.reloadIfChanged(report);
    mCombine.program.reloadIfChanged(report);
}

} // namespace ispm
