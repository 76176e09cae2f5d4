// The viewer's reference: an image loaded from disk (`--reference`) or the path tracer run
// progressively inside the viewer, shown as the "reference", "side by side" and "error heat map"
// debug views, with relMSE and SSIM against the ispm total computed on request.
#pragma once

#include "gl/objects.h"
#include "gl/timer.h"
#include "image/image.h"
#include "render/frame.h"
#include "render/reference_pass.h"
#include "render/reloadable_program.h"
#include "viewer/debug_view.h"

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace ispm {

class ReferenceView {
  public:
    // `timing`: how the path tracer's samples are timed for the Stats panel (as the passes).
    explicit ReferenceView(gl::TimingMethod timing);

    // Throws InputError naming the file when it cannot be read as an image.
    void load(const std::string& path);
    void setRendering(bool rendering);
    // The scene, the camera, the settings or the lights changed: the rendered reference starts
    // over (once the camera has been still for a moment, so flying does not rebuild it every
    // frame), and the metrics shown, which describe the old view, go.
    void restart();
    // After the frame: adds this frame's samples to the rendered reference (built from `scene`
    // and the runner's settings) and refreshes the metrics when they are set to follow.
    void update(const Scene& scene, const FrameRunner& runner);
    // A reference to show and compare: rendered, or loaded at the render's size (`width` x
    // `height`); one of another size is refused with a message, never stretched.
    bool hasReference(int width, int height) const { return getSource(width, height) != nullptr; }
    // Why there is no reference to show or compare at that size (empty when there is one).
    std::string describeMissing(int width, int height) const;
    // The path tracer's time this frame (by the timing method given), when it added samples.
    std::optional<PassTiming> getFrameTiming() const { return mFrameTiming; }
    const std::string& getMetricsText() const { return mMetricsText; }
    const std::string& getStatus() const { return mStatus; }

    // relMSE and SSIM of the runner's total against the reference, read back now; the text also
    // shows in the panel. Size mismatches and a missing reference give a message, not a throw.
    std::string computeMetrics(const FrameRunner& runner);

    // Draws into the default framebuffer's region [0, width) x [0, height) with the linear
    // views' encoding (x 2^stops, gamma); the heat map's legend labels go over it through ImGui.
    void draw(const FrameRunner& runner, ReferenceMode mode, float exposureStops, int width,
              int height) const;
    void drawLegendLabels(int height) const;
    // The Reference panel's contents; `runner` for the metrics button.
    void drawPanel(const FrameRunner& runner);
    void reloadPrograms(ShaderReloadReport& report) { mProgram.reloadIfChanged(report); }

  private:
    const gl::Texture* getSource(int width, int height) const;
    // The loaded image's size against the render's, as the panel says it (empty when it fits).
    std::string describeSizeMismatch(int width, int height) const;

    ReloadableProgram mProgram;
    gl::Buffer mParams; // gpu::ReferenceViewParams
    gl::VertexArray mVertexArray;
    gl::Sampler mSampler;
    gl::Texture mLoaded; // rgb = radiance, a = 1 (one "sample")
    Image mLoadedImage;
    std::string mLoadedPath;
    std::array<char, 512> mPathInput{};
    std::unique_ptr<ReferencePass> mPass;
    bool mRendering = false;
    int mSamplesPerFrame = 1;
    int mStillFrames = 0;
    float mHeatMax = 1.0f; // relative error at the top of the false-colour scale
    bool mAutoMetrics = false;
    int mFramesSinceMetrics = 0;
    std::string mMetricsText;
    std::string mStatus;
    gl::PassTimer mTimer;
    std::optional<PassTiming> mFrameTiming;
    double mLastTracedMs = 0.0; // the newest time the timer gave (a few frames late on GPUs)
};

} // namespace ispm
