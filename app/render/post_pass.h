// Post-processing in linear HDR between compose and tone map: motion blur (along the G-buffer's
// velocity channel), depth blur (a thin lens's circle of confusion from the G-buffer's depth)
// and bloom (the light above a threshold spread by a Gaussian). Each redistributes the image's
// radiance without adding or losing any: the sum over the image is kept. The frame runner chains
// the ones that are on (setInput), in that order; with all off none runs and the composed image
// goes to the tone map as it is.
#pragma once

#include "render/fullscreen.h"
#include "render/gbuffer.h"
#include "render/param_blocks.h"
#include "render/pass.h"

#include <shared/post_data.h>

namespace ispm {

// The parameters every post pass reads, from the frame's settings and camera.
gpu::PostParams computePostParams(const FrameInputs& inputs);

// One full-screen draw into an RGBA32F target with its own program (the post passes' steps).
// The passes size their targets when they run (memory only while an effect is on).
struct PostStep {
    PostStep(const std::string& label, const std::string& fragmentPath);
    void draw() const;
    size_t getGpuBytes() const; // 0 until the target is made

    ColorTarget target;
    ReloadableProgram program;
    gl::VertexArray vertexArray;
};

// motion_blur_shutter: every pixel's radiance is split into equal samples along its streak (its
// velocity times the shutter, centred on it) and each is added where it lands (compute, float
// adds by compare-and-swap), then copied into the output.
class MotionBlurPass final : public Pass {
  public:
    explicit MotionBlurPass(const GBuffer& viewer);
    const char* getName() const override { return "motion_blur"; }
    void setInput(const gl::Texture& hdr) { mInput = &hdr; }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override;
    const gl::Texture& getOutput() const { return mResolve.target.getTexture(); }
    size_t getGpuBytes() const { return mScattered.getSize() + mResolve.getGpuBytes(); }

  private:
    const GBuffer& mViewer;
    const gl::Texture* mInput = nullptr;
    ReloadableProgram mScatter;
    gl::Buffer mScattered; // 3 floats a pixel
    ParamBlocks<gpu::PostParams> mParams;
    PostStep mResolve;
};

// dof_aperture_m: every pixel's radiance is spread evenly over its circle of confusion (the
// `coc` step divides it by the disc's in-image weight and finds the largest radius), gathered
// back as a scatter would (`gather`): the image's sum is kept, and an in-focus pixel takes light
// only from out-of-focus neighbours whose circles reach it.
class DepthBlurPass final : public Pass {
  public:
    explicit DepthBlurPass(const GBuffer& viewer);
    const char* getName() const override { return "depth_blur"; }
    void setInput(const gl::Texture& hdr) { mInput = &hdr; }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override;
    const gl::Texture& getOutput() const { return mGather.target.getTexture(); }
    size_t getGpuBytes() const { return mCoc.getGpuBytes() + mGather.getGpuBytes(); }

  private:
    const GBuffer& mViewer;
    const gl::Texture* mInput = nullptr;
    gl::Buffer mCocMax; // uint: the largest radius this frame, px, rounded up
    ParamBlocks<gpu::PostParams> mParams;
    PostStep mCoc;    // rgb = radiance / disc weight, a = radius px
    PostStep mGather; // the blurred radiance
};

// bloom_intensity: the part of each pixel above bloom_threshold, times the intensity, is taken
// out (`extract`) and blurred by a separable Gaussian with mirrored edges (whose weights then sum
// to one for every source pixel, at the image's borders too), then added back.
class BloomPass final : public Pass {
  public:
    BloomPass();
    const char* getName() const override { return "bloom"; }
    void setInput(const gl::Texture& hdr) { mInput = &hdr; }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override;
    const gl::Texture& getOutput() const { return mCombine.target.getTexture(); }
    size_t getGpuBytes() const {
        return mExtract.getGpuBytes() + mBlurX.getGpuBytes() + mCombine.getGpuBytes();
    }

  private:
    const gl::Texture* mInput = nullptr;
    ParamBlocks<gpu::PostParams> mParams; // [0] horizontal blur, [1] vertical blur + combine
    PostStep mExtract;
    PostStep mBlurX;
    PostStep mCombine;
};

} // namespace ispm
