// FullscreenTarget: owns its program, output texture and framebuffer.
#include "render/fullscreen.h"

#include "gl/state.h"

namespace ispm {

FullscreenTarget::FullscreenTarget(std::string label, gl::Format format,
                                   const std::string& fragmentPath,
                                   std::vector<std::string> defines)
    : mLabel(std::move(label)), mFormat(format),
      mProgram(ReloadableProgram({.label = mLabel,
                                  .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                             {gl::ShaderStage::Fragment, fragmentPath}},
                                  .defines = std::move(defines)})),
      mVertexArray(mLabel + " vao") {}

void FullscreenTarget::resize(int width, int height) {
    if (mTexture.getWidth() == width && mTexture.getHeight() == height) return;
    mTexture = gl::Texture::create2D(mLabel, mFormat, width, height);
    mFramebuffer = gl::Framebuffer(mLabel + " target");
    mFramebuffer.attachColor(0, mTexture);
    mFramebuffer.setDrawBufferCount(1);
    mFramebuffer.checkComplete();
}

void FullscreenTarget::draw() const {
    mFramebuffer.bind();
    gl::applyState({});
    mProgram.use();
    mVertexArray.bind();
    constexpr int kFullscreenVertices = 3;
    gl::drawArrays(gl::Primitive::Triangles, 0, kFullscreenVertices);
}

} // namespace ispm
