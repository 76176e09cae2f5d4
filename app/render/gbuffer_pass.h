// Viewer G-buffer pass and light-view pass: the scene seen from the camera and from every light
// camera, into the channels of the G-buffer table. Light views double as shadow maps.
#pragma once

#include "render/gbuffer.h"
#include "render/pass.h"

namespace ispm {

class GBufferPass final : public Pass {
  public:
    GBufferPass();
    const char* getName() const override { return "gbuffer"; }
    void resize(int width, int height) override;
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override { mPrograms.reloadIfChanged(report); }
    const GBuffer& getGBuffer() const { return mGBuffer; }
    // Draw the velocity channel without motion blur too (the viewer showing it).
    void setKeepMotion(bool keep) { mKeepMotion = keep; }

  private:
    GBufferPrograms mPrograms;
    ParamBlocks<gpu::GBufferParams> mParams;
    gl::VertexArray mVertexArray;
    GBuffer mGBuffer;
    // The camera of the last frame drawn (its sub-pixel offset included), for the velocity
    // channel; none after a resize.
    glm::mat4 mPreviousClipFromWorld{1.0f};
    glm::vec2 mPreviousJitterPx{0.0f}; // its sub-pixel offset
    bool mHasPrevious = false;
    bool mKeepMotion = false;
};

class LightViewPass final : public Pass {
  public:
    LightViewPass();
    const char* getName() const override { return "light_views"; }
    void execute(const FrameInputs& inputs) override;
    // The light cameras (layers) this frame draws, and views [firstView, firstView + viewCount)
    // of them alone (a frame drawn in slices); execute() draws them all.
    static size_t getViewCount(const FrameInputs& inputs);
    void executeViews(const FrameInputs& inputs, size_t firstView, size_t viewCount);
    void reloadPrograms(ShaderReloadReport& report) override { mPrograms.reloadIfChanged(report); }
    const GBuffer& getGBuffer() const { return mGBuffer; }

  private:
    void prepare(const FrameInputs& inputs); // the G-buffer's size, every view's blocks
    GBufferPrograms mPrograms;
    ParamBlocks<gpu::GBufferParams> mParams;
    std::vector<std::vector<uint32_t>> mDrawOrders; // per view (computeDrawOrder)
    gl::VertexArray mVertexArray;
    GBuffer mGBuffer;
};

} // namespace ispm
