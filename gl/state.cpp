// Applies PipelineState values and wraps the GL commands the passes issue.
#include "gl/state.h"

#include "gl/gl.h"

namespace gl {
namespace {

void setEnabled(GLenum capability, bool enabled) {
    if (enabled) {
        glEnable(capability);
    } else {
        glDisable(capability);
    }
}

} // namespace

void applyState(const PipelineState& state) {
    setEnabled(GL_DEPTH_TEST, state.depthTest != DepthTest::Off);
    if (state.depthTest != DepthTest::Off) {
        glDepthFunc(state.depthTest == DepthTest::Less ? GL_LESS : GL_LEQUAL);
    }
    glDepthMask(state.depthWrite ? GL_TRUE : GL_FALSE);
    setEnabled(GL_BLEND, state.blend != Blend::Off);
    if (state.blend == Blend::Additive) {
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    }
    setEnabled(GL_CULL_FACE, state.cull != Cull::Off);
    if (state.cull != Cull::Off) glCullFace(state.cull == Cull::Back ? GL_BACK : GL_FRONT);
    setEnabled(GL_RASTERIZER_DISCARD, state.rasterizerDiscard);
    setEnabled(GL_PROGRAM_POINT_SIZE, state.programPointSize);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void memoryBarrier(Barrier barriers) {
    glMemoryBarrier(static_cast<GLbitfield>(barriers));
}

void drawArrays(Primitive primitive, int first, int count) {
    glDrawArrays(static_cast<GLenum>(primitive), first, count);
}

void drawArraysInstanced(Primitive primitive, int first, int count, int instances) {
    glDrawArraysInstanced(static_cast<GLenum>(primitive), first, count, instances);
}

void drawArraysIndirect(Primitive primitive, const Buffer& arguments, size_t offsetBytes) {
    arguments.bind(BufferTarget::DrawIndirect);
    glDrawArraysIndirect(static_cast<GLenum>(primitive),
                         reinterpret_cast<const void*>(static_cast<uintptr_t>(offsetBytes)));
    Buffer::unbind(BufferTarget::DrawIndirect);
}

void drawElementsIndirect(Primitive primitive, const Buffer& arguments, size_t offsetBytes) {
    arguments.bind(BufferTarget::DrawIndirect);
    glDrawElementsIndirect(static_cast<GLenum>(primitive), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(static_cast<uintptr_t>(offsetBytes)));
    Buffer::unbind(BufferTarget::DrawIndirect);
}

void dispatchCompute(unsigned groupsX, unsigned groupsY, unsigned groupsZ) {
    glDispatchCompute(groupsX, groupsY, groupsZ);
}

void dispatchComputeIndirect(const Buffer& arguments, size_t offsetBytes) {
    arguments.bind(BufferTarget::DispatchIndirect);
    glDispatchComputeIndirect(static_cast<GLintptr>(offsetBytes));
    Buffer::unbind(BufferTarget::DispatchIndirect);
}

void finish() {
    glFinish();
}

void bindDefaultFramebuffer(int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
}

void setViewport(int x, int y, int width, int height) {
    glViewport(x, y, width, height);
}

void clearDefaultFramebuffer(const glm::vec4& colour) {
    glClearColor(colour.r, colour.g, colour.b, colour.a);
    glClear(GL_COLOR_BUFFER_BIT);
}

std::vector<uint8_t> readDefaultFramebuffer(int width, int height) {
    constexpr size_t kChannels = 4; // RGBA8: rows stay 4-byte aligned at any width
    std::vector<uint8_t> bytes(static_cast<size_t>(width) * static_cast<size_t>(height) *
                               kChannels);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    return bytes;
}

} // namespace gl
