// ColorTarget and FullscreenTarget: output textures, their framebuffers and the full-screen draw.
#include "render/fullscreen.h"

#include "gl/state.h"

namespace ispm {

void ColorTarget::resize(int width, int height) {
    if (mTexture.getWidth() == width && mTexture.getHeight() == height) return;
    mTexture = gl::Texture::create2D(mLabel, mFormat, width, height);
    mFramebuffer = gl::Framebuffer(mLabel + " target");
    mFramebuffer.attachColor(0, mTexture);
    mFramebuffer.setDrawBufferCount(1);
    mFramebuffer.checkComplete();
}

void drawFullscreenTriangle() {
    constexpr int kFullscreenVertices = 3;
    gl::drawArrays(gl::Primitive::Triangles, 0, kFullscreenVertices);
}

FullscreenTarget::FullscreenTarget(std::string label, gl::Format format,
                                   const std::string& fragmentPath,
                                   std::vector<std::string> defines)
    : mTarget(label, format),
      mPrograms({.label = label,
                 .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                            {gl::ShaderStage::Fragment, fragmentPath}},
                 .defines = std::move(defines)}),
      mVertexArray(label + " vao") {
    mPrograms.get({}); // a broken shader fails here, at start-up
}

void FullscreenTarget::draw(const gl::PipelineState& state, const std::optional<PixelRect>& rect,
                            const std::vector<std::string>& defines) {
    mTarget.bind();
    if (rect) gl::setViewport(rect->x, rect->y, rect->width, rect->height);
    gl::applyState(state);
    mPrograms.get(defines).use();
    mVertexArray.bind();
    drawFullscreenTriangle();
}

} // namespace ispm
