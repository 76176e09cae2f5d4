// Pipeline state as a value: each pass states what it needs and applies it, so nothing leaks
// from one pass (or ImGui) into the next. Also the draw, dispatch and barrier commands.
#pragma once

#include "gl/objects.h"

namespace gl {

enum class Blend { Off, Additive };
enum class Cull { Off, Back, Front };
enum class DepthTest { Off, Less, LessEqual };

struct PipelineState {
    DepthTest depthTest = DepthTest::Off;
    bool depthWrite = false;
    Blend blend = Blend::Off;
    Cull cull = Cull::Off;
    bool rasterizerDiscard = false;
    bool programPointSize = false;
};

void applyState(const PipelineState& state);

enum class Barrier : GLbitfield {
    Storage = GL_SHADER_STORAGE_BARRIER_BIT,
    Command = GL_COMMAND_BARRIER_BIT,
    TextureFetch = GL_TEXTURE_FETCH_BARRIER_BIT,
    ImageAccess = GL_SHADER_IMAGE_ACCESS_BARRIER_BIT,
    AtomicCounter = GL_ATOMIC_COUNTER_BARRIER_BIT,
    VertexAttrib = GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT,
    TransformFeedback = GL_TRANSFORM_FEEDBACK_BARRIER_BIT,
    Framebuffer = GL_FRAMEBUFFER_BARRIER_BIT,
    QueryBuffer = GL_QUERY_BUFFER_BARRIER_BIT,
    BufferUpdate = GL_BUFFER_UPDATE_BARRIER_BIT,
    TextureUpdate = GL_TEXTURE_UPDATE_BARRIER_BIT,
    All = GL_ALL_BARRIER_BITS,
};

inline Barrier operator|(Barrier a, Barrier b) {
    return static_cast<Barrier>(static_cast<GLbitfield>(a) | static_cast<GLbitfield>(b));
}

void memoryBarrier(Barrier barriers);
void drawArrays(Primitive primitive, int first, int count);
void drawArraysInstanced(Primitive primitive, int first, int count, int instances);
// Arguments {count, instanceCount, first, baseInstance} at offsetBytes in `arguments`.
void drawArraysIndirect(Primitive primitive, const Buffer& arguments, size_t offsetBytes);
// 32-bit indexed draw with arguments {count, instanceCount, firstIndex, baseVertex, baseInstance}
// at offsetBytes in `arguments`, from the bound vertex array's element buffer.
void drawElementsIndirect(Primitive primitive, const Buffer& arguments, size_t offsetBytes);
void dispatchCompute(unsigned groupsX, unsigned groupsY = 1, unsigned groupsZ = 1);
// Group counts {x, y, z} at offsetBytes in `arguments`, written on the GPU.
void dispatchComputeIndirect(const Buffer& arguments, size_t offsetBytes);
void finish();
// Binds the default framebuffer (a window's back buffer) with the given viewport.
void bindDefaultFramebuffer(int width, int height);
// The viewport alone, within whatever framebuffer is bound.
void setViewport(int x, int y, int width, int height);
// Clears the bound default framebuffer's colour.
void clearDefaultFramebuffer(const glm::vec4& colour);
// The default framebuffer's back buffer as RGBA8, bottom row first (GL's order).
std::vector<uint8_t> readDefaultFramebuffer(int width, int height);

} // namespace gl
