// ReferencePass: a progressive compute path tracer over the same GPU scene, BVH, materials and
// lights as the photon mapper. Each call to addSample() adds one jittered sample per pixel to a
// float accumulation image; the same seed gives the same image. With reference_method = light,
// a sample is instead one light path per pixel, each connected to the camera at every diffuse or
// glossy vertex (caustics from point, spot and sun lights converge).
#pragma once

#include "gl/objects.h"
#include "gl/program.h"
#include "image/image.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"
#include "settings/frame_settings.h"

#include <memory>

namespace ispm {

// Bounces when neither the scene nor the command line sets them: enough for a converged image
// (Russian roulette ends long paths before that).
inline constexpr int kReferenceDefaultBounces = 64;

class ReferencePass {
  public:
    // Builds its own GPU scene (BVH included): the command line's reference renders.
    ReferencePass(const Scene& scene, const Settings& settings);
    // Borrows the frame's GPU scene (the viewer's: no second BVH at every restart); it must
    // outlive the pass.
    ReferencePass(const Scene& scene, const GpuScene& gpuScene, const Settings& settings);
    void addSample();
    int getSampleCount() const { return mSamples; }
    // Sum of the samples so far (rgb) and their count (a).
    const gl::Texture& getAccumulation() const { return mAccumulation; }
    // Mean radiance per pixel so far, row 0 at the top.
    Image readMean() const;
    int getBounces() const { return mBounces; }
    uint32_t getMethod() const { return mMethod; } // gpu::kReferencePath or kReferenceLight

  private:
    ReferencePass(const Scene& scene, std::unique_ptr<GpuScene> owned, const GpuScene* borrowed,
                  const FrameSettings& settings);

    const Scene& mScene;
    std::unique_ptr<GpuScene> mOwnedScene; // null when borrowed
    const GpuScene& mGpuScene;
    void addPathSample();
    void addLightSample();

    gl::Program mProgram;        // reference.comp, or light_trace.comp for the light method
    gl::Program mResolveProgram; // light_resolve.comp (light method only)
    gl::Buffer mFrameConstants;
    gl::Buffer mParams; // gpu::ReferenceParams or gpu::LightTraceParams of the sample being added
    gl::Buffer mSplat;  // light method: rgb floats per pixel of the sample being added
    gl::Texture mAccumulation;
    int mWidth;
    int mHeight;
    int mBounces;
    uint32_t mSeed;
    uint32_t mMethod;
    float mPixelAreaM2 = 0.0f; // one pixel on the image plane 1 m from the eye (light method)
    int mSamples = 0;
};

} // namespace ispm
