// A full-screen triangle drawn into one colour texture: the common body of the deferred passes.
#pragma once

#include "gl/objects.h"
#include "gl/state.h"
#include "render/pixel_rect.h"
#include "render/reloadable_program.h"

#include <optional>
#include <string>
#include <vector>

namespace ispm {

// One colour texture and the framebuffer that draws into it, made anew when the size changes.
class ColorTarget {
  public:
    ColorTarget(std::string label, gl::Format format) : mLabel(std::move(label)), mFormat(format) {}
    void resize(int width, int height);
    void bind() const { mFramebuffer.bind(); } // with the viewport
    void clear(const glm::vec4& colour) const { mFramebuffer.clearColor(0, colour); }
    const gl::Texture& getTexture() const { return mTexture; }

  private:
    std::string mLabel;
    gl::Format mFormat;
    gl::Texture mTexture;
    gl::Framebuffer mFramebuffer;
};

// Draws the triangle that covers the viewport (lib/fullscreen.vert makes it from gl_VertexID),
// with whatever program and vertex array are bound.
void drawFullscreenTriangle();

class FullscreenTarget {
  public:
    FullscreenTarget(std::string label, gl::Format format, const std::string& fragmentPath,
                     std::vector<std::string> defines);
    void resize(int width, int height) { mTarget.resize(width, height); }
    // Binds the target, applies a plain state (no depth, no blending) and draws.
    void draw() { draw({}, std::nullopt); }
    // Binds the target, applies `state` and draws with the program variant of `defines` (built
    // at its first use; ProgramVariants) over `rect` alone (the viewport; gl_FragCoord stays the
    // target's pixel) or, without one, the whole target.
    void draw(const gl::PipelineState& state, const std::optional<PixelRect>& rect,
              const std::vector<std::string>& defines = {});
    const gl::Texture& getTexture() const { return mTarget.getTexture(); }
    void reloadProgram(ShaderReloadReport& report) { mPrograms.reloadIfChanged(report); }

  private:
    ColorTarget mTarget;
    ProgramVariants mPrograms; // the plain one built with the target
    gl::VertexArray mVertexArray;
};

} // namespace ispm
