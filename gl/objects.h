// RAII wrappers over OpenGL 4.5 DSA objects: Buffer, Texture, Sampler, Framebuffer, VertexArray,
// Query, TransformFeedback (Program is in program.h). Each is move-only and carries a debug label.
// Raw GLenums stay behind the enum classes here.
#pragma once

#include "gl/handle.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace gl {

enum class Format : GLenum {
    RGBA32F = GL_RGBA32F,
    RGBA16F = GL_RGBA16F,
    RGBA8 = GL_RGBA8,
    SRGB8A8 = GL_SRGB8_ALPHA8, // colour textures: sampling decodes sRGB to linear
    RG32F = GL_RG32F,
    RG16F = GL_RG16F,
    R32F = GL_R32F,
    R32UI = GL_R32UI,
    Depth32F = GL_DEPTH_COMPONENT32F,
};

enum class BufferTarget : GLenum {
    Storage = GL_SHADER_STORAGE_BUFFER,
    Uniform = GL_UNIFORM_BUFFER,
    AtomicCounter = GL_ATOMIC_COUNTER_BUFFER,
    TransformFeedback = GL_TRANSFORM_FEEDBACK_BUFFER,
    DrawIndirect = GL_DRAW_INDIRECT_BUFFER,
    DispatchIndirect = GL_DISPATCH_INDIRECT_BUFFER,
    QueryResult = GL_QUERY_BUFFER,
};

class Buffer {
  public:
    Buffer() = default;
    // Immutable storage, updatable with upload(); data may be null (zero-filled).
    Buffer(std::string_view label, size_t bytes, const void* data = nullptr);
    template <typename T> static Buffer fromSpan(std::string_view label, std::span<const T> items) {
        return Buffer(label, items.size_bytes(), items.data());
    }

    // Contents are GPU state, not the handle's: writing them through a const handle is allowed,
    // as through a const pointer.
    void upload(size_t offsetBytes, size_t bytes, const void* data) const;
    template <typename T> void upload(std::span<const T> items, size_t offsetBytes = 0) const {
        upload(offsetBytes, items.size_bytes(), items.data());
    }
    // Waits for the GPU. A read of at most kStagedReadBytes goes through a small buffer of this
    // one's own (a GPU copy, then the read): a driver that moves a buffer read often by the host
    // into host memory (NVIDIA's does) then moves that one, not the counters the shaders use.
    void download(size_t offsetBytes, size_t bytes, void* out) const;
    static constexpr size_t kStagedReadBytes = 64 * 1024;
    template <typename T> std::vector<T> read(size_t count, size_t offsetBytes = 0) const {
        std::vector<T> items(count);
        download(offsetBytes, count * sizeof(T), items.data());
        return items;
    }
    void clearToZero() const;
    // Zeroes bytes [offsetBytes, offsetBytes + bytes), both multiples of 4.
    void clearRangeToZero(size_t offsetBytes, size_t bytes) const;

    void bindBase(BufferTarget target, GLuint index) const;
    void bindRange(BufferTarget target, GLuint index, size_t offsetBytes, size_t bytes) const;
    void bind(BufferTarget target) const;
    static void unbind(BufferTarget target);

    GLuint getId() const { return mHandle.get(); }
    size_t getSize() const { return mSize; }

  private:
    Handle<deleteBuffer> mHandle;
    size_t mSize = 0;
    mutable Handle<deleteBuffer> mStaging; // download's copy of small reads
    mutable size_t mStagingSize = 0;
};

enum class Filter { Nearest, Linear };
enum class Wrap { ClampToEdge, Repeat };

class Texture {
  public:
    Texture() = default;
    static Texture create2D(std::string_view label, Format format, int width, int height);
    // Layers of one size: the faces of a point light, for instance.
    static Texture create2DArray(std::string_view label, Format format, int width, int height,
                                 int layers);
    // A mipmapped, repeating, trilinear 2D array (colour textures): `levels` down to 1x1 at most.
    static Texture createMipmapped2DArray(std::string_view label, Format format, int width,
                                          int height, int layers, int levels);

    // Reads one level-0 layer (or the whole 2D texture) as RGBA floats, row 0 at the bottom.
    std::vector<glm::vec4> readRgba(int layer = 0) const;
    std::vector<float> readDepth(int layer = 0) const;
    void uploadRgba(std::span<const glm::vec4> texels, int layer = 0);
    // 8-bit RGBA texels of level 0, row 0 first (as an image file's top row; a texture's t = 0).
    void uploadRgba8(std::span<const uint8_t> texels, int layer);
    void generateMipmaps() const; // levels 1.. from level 0
    void clear(const glm::vec4& value);
    // Copies level 0 of `source` (same size and format; 2D) into this texture on the GPU.
    void copyFrom(const Texture& source) const; // GPU contents only: the object is unchanged
    // This texture's size of `source` from texel (x, y) on, to this texture's (0, 0).
    void copyFrom(const Texture& source, int x, int y) const;

    void bindUnit(GLuint unit) const;
    void bindImage(GLuint unit, bool read, bool write) const;

    GLuint getId() const { return mHandle.get(); }
    int getWidth() const { return mWidth; }
    int getHeight() const { return mHeight; }
    int getLayers() const { return mLayers; }
    Format getFormat() const { return mFormat; }
    bool isArray() const { return mIsArray; }

  private:
    Handle<deleteTexture> mHandle;
    Format mFormat = Format::RGBA8;
    int mWidth = 0;
    int mHeight = 0;
    int mLayers = 1;
    bool mIsArray = false;
};

class Sampler {
  public:
    Sampler() = default;
    Sampler(std::string_view label, Filter filter, Wrap wrap);
    void bindUnit(GLuint unit) const;
    static void unbindUnit(GLuint unit); // the texture's own sampling state again
    GLuint getId() const { return mHandle.get(); }

  private:
    Handle<deleteSampler> mHandle;
};

class Framebuffer {
  public:
    Framebuffer() = default;
    explicit Framebuffer(std::string_view label);
    // layer < 0 attaches the whole texture (a layered attachment for arrays).
    void attachColor(int index, const Texture& texture, int layer = -1);
    void attachDepth(const Texture& texture, int layer = -1);
    // Selects colour attachments 0..count-1 as draw buffers.
    void setDrawBufferCount(int count);
    // Of attachments 0..count-1, those whose bit is set in `mask`: draw buffer i is attachment i
    // or none (fragment output i is dropped, the attachment neither read nor written).
    void setDrawBuffers(int count, uint32_t mask);
    // Size for drawing with no attachments (transform feedback with rasterizer discard needs a
    // complete framebuffer; framebuffer 0 does nothing in a headless context).
    void setDefaultSize(int width, int height);
    void checkComplete() const; // throws gl::Error naming the label
    void bind() const;          // binds and sets the viewport to its size
    // Both open the write masks they need (GL clears obey glDepthMask/glColorMask).
    void clearColor(int index, const glm::vec4& value) const;
    void clearDepth(float depth) const;
    GLuint getId() const { return mHandle.get(); }
    int getWidth() const { return mWidth; }
    int getHeight() const { return mHeight; }

  private:
    Handle<deleteFramebuffer> mHandle;
    std::string mLabel;
    int mWidth = 0;
    int mHeight = 0;
};

class VertexArray {
  public:
    VertexArray() = default;
    explicit VertexArray(std::string_view label);
    // Float vertex attribute `location` read from `buffer` with the given stride and offset.
    void setFloatAttribute(GLuint location, const Buffer& buffer, int components, size_t stride,
                           size_t offsetBytes);
    // The element (index) buffer indexed draws read: 32-bit indices.
    void setElementBuffer(const Buffer& buffer);
    void bind() const;
    GLuint getId() const { return mHandle.get(); }

  private:
    Handle<deleteVertexArray> mHandle;
};

enum class QueryTarget : GLenum {
    TimeElapsed = GL_TIME_ELAPSED,
    PrimitivesWritten = GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN,
    PrimitivesGenerated = GL_PRIMITIVES_GENERATED,
    SamplesPassed = GL_SAMPLES_PASSED,
};

class Query {
  public:
    Query() = default;
    Query(std::string_view label, QueryTarget target);
    void begin() const;
    void end() const;
    uint64_t getResult() const;     // waits for the result
    bool isResultAvailable() const; // without waiting
    // Writes the 32-bit result into `buffer` at offsetBytes on the GPU (ARB_query_buffer_object).
    void writeResultTo(const Buffer& buffer, size_t offsetBytes) const;
    GLuint getId() const { return mHandle.get(); }

  private:
    Handle<deleteQuery> mHandle;
    QueryTarget mTarget = QueryTarget::TimeElapsed;
};

enum class Primitive : GLenum {
    Points = GL_POINTS,
    Lines = GL_LINES,
    Triangles = GL_TRIANGLES,
    TriangleStrip = GL_TRIANGLE_STRIP,
};

class TransformFeedback {
  public:
    TransformFeedback() = default;
    explicit TransformFeedback(std::string_view label);
    void attachBuffer(GLuint index, const Buffer& buffer, size_t offsetBytes, size_t bytes);
    // Binds this object and begins capture of `primitive` (rasterizer discard is the caller's).
    void begin(Primitive primitive) const;
    void end() const;
    GLuint getId() const { return mHandle.get(); }

  private:
    Handle<deleteTransformFeedback> mHandle;
};

} // namespace gl
