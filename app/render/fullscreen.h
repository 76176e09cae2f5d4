// A full-screen triangle drawn into one colour texture: the common body of the deferred passes.
#pragma once

#include "gl/objects.h"
#include "render/reloadable_program.h"

#include <string>
#include <vector>

namespace ispm {

class FullscreenTarget {
public:
    FullscreenTarget(std::string label, gl::Format format, const std::string& fragmentPath,
                     std::vector<std::string> defines);
    void resize(int width, int height);
    // Binds the target, applies a plain state (no depth, no blending) and draws.
    void draw() const;
    const gl::Texture& getTexture() const { return mTexture; }
    void reloadProgram(ShaderReloadReport& report) { mProgram.reloadIfChanged(report); }

private:
    std::string mLabel;
    gl::Format mFormat;
    ReloadableProgram mProgram;
    gl::VertexArray mVertexArray;
    gl::Texture mTexture;
    gl::Framebuffer mFramebuffer;
};

} // namespace ispm
