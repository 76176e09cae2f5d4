// ReferencePass: a progressive compute path tracer over the same GPU scene, BVH, materials and
// lights as the photon mapper. Each call to addSample() adds one jittered sample per pixel to a
// float accumulation image; the same seed gives the same image.
#pragma once

#include "gl/objects.h"
#include "gl/program.h"
#include "image/image.h"
#include "render/gpu_scene.h"
#include "scene/frame_settings.h"
#include "scene/scene.h"

namespace ispm {

// Bounces when neither the scene nor the command line sets them: enough for a converged image
// (Russian roulette ends long paths before that).
inline constexpr int kReferenceDefaultBounces = 64;

class ReferencePass {
public:
    ReferencePass(const Scene& scene, const Settings& settings); // resolves them
    ReferencePass(const Scene& scene, const FrameSettings& settings);
    void addSample();
    int getSampleCount() const { return mSamples; }
    // Sum of the samples so far (rgb) and their count (a).
    const gl::Texture& getAccumulation() const { return mAccumulation; }
    // Mean radiance per pixel so far, row 0 at the top.
    Image readMean() const;
    int getBounces() const { return mBounces; }

private:
    const Scene& mScene;
    GpuScene mGpuScene;
    gl::Program mProgram;
    gl::Buffer mFrameConstants;
    gl::Texture mAccumulation;
    int mWidth;
    int mHeight;
    int mBounces;
    uint32_t mSeed;
    int mSamples = 0;
};

} // namespace ispm
