// DSA implementations of the object wrappers; every create is labelled for debuggers and logs.
#include "gl/objects.h"

#include "gl/gl.h"

#include <cassert>

namespace gl {

void deleteBuffer(GLuint id) {
    glDeleteBuffers(1, &id);
}
void deleteTexture(GLuint id) {
    glDeleteTextures(1, &id);
}
void deleteSampler(GLuint id) {
    glDeleteSamplers(1, &id);
}
void deleteFramebuffer(GLuint id) {
    glDeleteFramebuffers(1, &id);
}
void deleteVertexArray(GLuint id) {
    glDeleteVertexArrays(1, &id);
}
void deleteProgram(GLuint id) {
    glDeleteProgram(id);
}
void deleteQuery(GLuint id) {
    glDeleteQueries(1, &id);
}
void deleteTransformFeedback(GLuint id) {
    glDeleteTransformFeedbacks(1, &id);
}

void setLabel(GLenum kind, GLuint id, std::string_view label) {
    if (!label.empty()) {
        glObjectLabel(kind, id, static_cast<GLsizei>(label.size()), label.data());
    }
}

// ---- Buffer ----

Buffer::Buffer(std::string_view label, size_t bytes, const void* data) : mSize(bytes) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    mHandle = Handle<deleteBuffer>(id);
    // A zero-sized store is not allowed; keep one word so empty inputs still bind.
    const size_t storageBytes = bytes == 0 ? sizeof(uint32_t) : bytes;
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(storageBytes), bytes == 0 ? nullptr : data,
                         GL_DYNAMIC_STORAGE_BIT);
    if (!data || bytes == 0) clearToZero();
    setLabel(GL_BUFFER, id, label);
}

void Buffer::upload(size_t offsetBytes, size_t bytes, const void* data) const {
    assert(offsetBytes + bytes <= mSize);
    if (bytes == 0) return;
    glNamedBufferSubData(getId(), static_cast<GLintptr>(offsetBytes),
                         static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::download(size_t offsetBytes, size_t bytes, void* out) const {
    assert(offsetBytes + bytes <= mSize);
    if (bytes == 0) return;
    // Shader writes reach buffer commands (the copy, the read) only after this barrier (GL 4.5
    // section 7.13.2); here, so that no caller has to remember it.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (bytes > kStagedReadBytes) {
        glGetNamedBufferSubData(getId(), static_cast<GLintptr>(offsetBytes),
                                static_cast<GLsizeiptr>(bytes), out);
        return;
    }
    if (!mStaging || mStagingSize < bytes) { // none yet (or moved away), or too small
        GLuint id = 0;
        glCreateBuffers(1, &id);
        mStaging = Handle<deleteBuffer>(id);
        mStagingSize = bytes;
        glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), nullptr, GL_CLIENT_STORAGE_BIT);
        setLabel(GL_BUFFER, id, "read-back staging");
    }
    glCopyNamedBufferSubData(getId(), mStaging.get(), static_cast<GLintptr>(offsetBytes), 0,
                             static_cast<GLsizeiptr>(bytes));
    glGetNamedBufferSubData(mStaging.get(), 0, static_cast<GLsizeiptr>(bytes), out);
}

void Buffer::clearToZero() const {
    const GLuint zero = 0;
    glClearNamedBufferData(getId(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void Buffer::clearRangeToZero(size_t offsetBytes, size_t bytes) const {
    assert(offsetBytes % 4 == 0 && bytes % 4 == 0 && offsetBytes + bytes <= mSize);
    const GLuint zero = 0;
    glClearNamedBufferSubData(getId(), GL_R32UI, static_cast<GLintptr>(offsetBytes),
                              static_cast<GLsizeiptr>(bytes), GL_RED_INTEGER, GL_UNSIGNED_INT,
                              &zero);
}

void Buffer::bindBase(BufferTarget target, GLuint index) const {
    glBindBufferBase(static_cast<GLenum>(target), index, getId());
}

void Buffer::bindRange(BufferTarget target, GLuint index, size_t offsetBytes, size_t bytes) const {
    glBindBufferRange(static_cast<GLenum>(target), index, getId(),
                      static_cast<GLintptr>(offsetBytes), static_cast<GLsizeiptr>(bytes));
}

void Buffer::bind(BufferTarget target) const {
    glBindBuffer(static_cast<GLenum>(target), getId());
}

void Buffer::unbind(BufferTarget target) {
    glBindBuffer(static_cast<GLenum>(target), 0);
}

// ---- Texture ----

namespace {

bool isDepthFormat(Format format) {
    return format == Format::Depth32F;
}

} // namespace

Texture Texture::create2D(std::string_view label, Format format, int width, int height) {
    assert(width > 0 && height > 0);
    Texture t;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    t.mHandle = Handle<deleteTexture>(id);
    glTextureStorage2D(id, 1, static_cast<GLenum>(format), width, height);
    t.mFormat = format;
    t.mWidth = width;
    t.mHeight = height;
    setLabel(GL_TEXTURE, id, label);
    return t;
}

Texture Texture::create2DArray(std::string_view label, Format format, int width, int height,
                               int layers) {
    assert(width > 0 && height > 0 && layers > 0);
    Texture t;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    t.mHandle = Handle<deleteTexture>(id);
    glTextureStorage3D(id, 1, static_cast<GLenum>(format), width, height, layers);
    t.mFormat = format;
    t.mWidth = width;
    t.mHeight = height;
    t.mLayers = layers;
    t.mIsArray = true;
    setLabel(GL_TEXTURE, id, label);
    return t;
}

Texture Texture::createMipmapped2DArray(std::string_view label, Format format, int width,
                                        int height, int layers, int levels) {
    assert(width > 0 && height > 0 && layers > 0 && levels > 0);
    Texture t;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    t.mHandle = Handle<deleteTexture>(id);
    glTextureStorage3D(id, levels, static_cast<GLenum>(format), width, height, layers);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
    t.mFormat = format;
    t.mWidth = width;
    t.mHeight = height;
    t.mLayers = layers;
    t.mIsArray = true;
    setLabel(GL_TEXTURE, id, label);
    return t;
}

void Texture::uploadRgba8(std::span<const uint8_t> texels, int layer) {
    [[maybe_unused]] constexpr size_t kRgbaBytes = 4;
    assert(mIsArray);
    assert(texels.size() ==
           static_cast<size_t>(mWidth) * static_cast<size_t>(mHeight) * kRgbaBytes);
    glTextureSubImage3D(getId(), 0, 0, 0, layer, mWidth, mHeight, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                        texels.data());
}

void Texture::generateMipmaps() const {
    glGenerateTextureMipmap(getId());
}

std::vector<glm::vec4> Texture::readRgba(int layer) const {
    assert(!isDepthFormat(mFormat));
    std::vector<glm::vec4> texels(static_cast<size_t>(mWidth) * static_cast<size_t>(mHeight));
    const auto bytes = static_cast<GLsizei>(texels.size() * sizeof(glm::vec4));
    glGetTextureSubImage(getId(), 0, 0, 0, layer, mWidth, mHeight, 1, GL_RGBA, GL_FLOAT, bytes,
                         texels.data());
    return texels;
}

std::vector<float> Texture::readDepth(int layer) const {
    assert(isDepthFormat(mFormat));
    std::vector<float> texels(static_cast<size_t>(mWidth) * static_cast<size_t>(mHeight));
    const auto bytes = static_cast<GLsizei>(texels.size() * sizeof(float));
    glGetTextureSubImage(getId(), 0, 0, 0, layer, mWidth, mHeight, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         bytes, texels.data());
    return texels;
}

void Texture::uploadRgba(std::span<const glm::vec4> texels, int layer) {
    assert(texels.size() == static_cast<size_t>(mWidth) * static_cast<size_t>(mHeight));
    if (mIsArray) {
        glTextureSubImage3D(getId(), 0, 0, 0, layer, mWidth, mHeight, 1, GL_RGBA, GL_FLOAT,
                            texels.data());
    } else {
        glTextureSubImage2D(getId(), 0, 0, 0, mWidth, mHeight, GL_RGBA, GL_FLOAT, texels.data());
    }
}

void Texture::copyFrom(const Texture& source) const {
    glCopyImageSubData(source.getId(), GL_TEXTURE_2D, 0, 0, 0, 0, getId(), GL_TEXTURE_2D, 0, 0, 0,
                       0, mWidth, mHeight, 1);
}

void Texture::copyFrom(const Texture& source, int x, int y) const {
    glCopyImageSubData(source.getId(), GL_TEXTURE_2D, 0, x, y, 0, getId(), GL_TEXTURE_2D, 0, 0, 0,
                       0, mWidth, mHeight, 1);
}

void Texture::clear(const glm::vec4& value) {
    if (isDepthFormat(mFormat)) {
        glClearTexImage(getId(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &value.x);
    } else {
        glClearTexImage(getId(), 0, GL_RGBA, GL_FLOAT, &value.x);
    }
}

void Texture::bindUnit(GLuint unit) const {
    glBindTextureUnit(unit, getId());
}

void Texture::bindImage(GLuint unit, bool read, bool write) const {
    const GLenum access = read && write ? GL_READ_WRITE : (write ? GL_WRITE_ONLY : GL_READ_ONLY);
    glBindImageTexture(unit, getId(), 0, mIsArray ? GL_TRUE : GL_FALSE, 0, access,
                       static_cast<GLenum>(mFormat));
}

// ---- Sampler ----

Sampler::Sampler(std::string_view label, Filter filter, Wrap wrap) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    mHandle = Handle<deleteSampler>(id);
    const GLint glFilter = filter == Filter::Linear ? GL_LINEAR : GL_NEAREST;
    const GLint glWrap = wrap == Wrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, glFilter);
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, glFilter);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, glWrap);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, glWrap);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, glWrap);
    setLabel(GL_SAMPLER, id, label);
}

void Sampler::bindUnit(GLuint unit) const {
    glBindSampler(unit, getId());
}

void Sampler::unbindUnit(GLuint unit) {
    glBindSampler(unit, 0);
}

// ---- Framebuffer ----

Framebuffer::Framebuffer(std::string_view label) : mLabel(label) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    mHandle = Handle<deleteFramebuffer>(id);
    setLabel(GL_FRAMEBUFFER, id, label);
}

void Framebuffer::attachColor(int index, const Texture& texture, int layer) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index);
    if (layer < 0) {
        glNamedFramebufferTexture(getId(), attachment, texture.getId(), 0);
    } else {
        glNamedFramebufferTextureLayer(getId(), attachment, texture.getId(), 0, layer);
    }
    mWidth = texture.getWidth();
    mHeight = texture.getHeight();
}

void Framebuffer::attachDepth(const Texture& texture, int layer) {
    if (layer < 0) {
        glNamedFramebufferTexture(getId(), GL_DEPTH_ATTACHMENT, texture.getId(), 0);
    } else {
        glNamedFramebufferTextureLayer(getId(), GL_DEPTH_ATTACHMENT, texture.getId(), 0, layer);
    }
    mWidth = texture.getWidth();
    mHeight = texture.getHeight();
}

void Framebuffer::setDrawBufferCount(int count) {
    setDrawBuffers(count, ~0u);
}

void Framebuffer::setDrawBuffers(int count, uint32_t mask) {
    constexpr int kMaxDrawBuffers = 8; // the GL 4.5 minimum of GL_MAX_DRAW_BUFFERS
    assert(count >= 0 && count <= kMaxDrawBuffers);
    GLenum buffers[kMaxDrawBuffers];
    for (int i = 0; i < count; ++i)
        buffers[i] = (mask >> i) & 1u ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i) : GL_NONE;
    if (count == 0) {
        glNamedFramebufferDrawBuffer(getId(), GL_NONE);
    } else {
        glNamedFramebufferDrawBuffers(getId(), count, buffers);
    }
}

void Framebuffer::setDefaultSize(int width, int height) {
    glNamedFramebufferParameteri(getId(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
    glNamedFramebufferParameteri(getId(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
    mWidth = width;
    mHeight = height;
}

void Framebuffer::checkComplete() const {
    const GLenum status = glCheckNamedFramebufferStatus(getId(), GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw Error("framebuffer '" + mLabel + "' is incomplete (status 0x" +
                    std::to_string(status) + ")");
    }
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, getId());
    glViewport(0, 0, mWidth, mHeight);
}

// Clears obey the write masks: open them, so a clear always clears whatever the last pass left.
void Framebuffer::clearColor(int index, const glm::vec4& value) const {
    glColorMaski(static_cast<GLuint>(index), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    glClearNamedFramebufferfv(getId(), GL_COLOR, index, &value.x);
}

void Framebuffer::clearDepth(float depth) const {
    glDepthMask(GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    glClearNamedFramebufferfv(getId(), GL_DEPTH, 0, &depth);
}

// ---- VertexArray ----

VertexArray::VertexArray(std::string_view label) {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    mHandle = Handle<deleteVertexArray>(id);
    setLabel(GL_VERTEX_ARRAY, id, label);
}

void VertexArray::setFloatAttribute(GLuint location, const Buffer& buffer, int components,
                                    size_t stride, size_t offsetBytes) {
    const GLuint binding = location; // one buffer binding per attribute keeps it simple
    glVertexArrayVertexBuffer(getId(), binding, buffer.getId(), static_cast<GLintptr>(offsetBytes),
                              static_cast<GLsizei>(stride));
    glVertexArrayAttribFormat(getId(), location, components, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(getId(), location, binding);
    glEnableVertexArrayAttrib(getId(), location);
}

void VertexArray::setElementBuffer(const Buffer& buffer) {
    glVertexArrayElementBuffer(getId(), buffer.getId());
}

void VertexArray::bind() const {
    glBindVertexArray(getId());
}

// ---- Query ----

Query::Query(std::string_view label, QueryTarget target) : mTarget(target) {
    GLuint id = 0;
    glCreateQueries(static_cast<GLenum>(target), 1, &id);
    mHandle = Handle<deleteQuery>(id);
    setLabel(GL_QUERY, id, label);
}

void Query::begin() const {
    glBeginQuery(static_cast<GLenum>(mTarget), getId());
}

void Query::end() const {
    glEndQuery(static_cast<GLenum>(mTarget));
}

uint64_t Query::getResult() const {
    GLuint64 value = 0;
    glGetQueryObjectui64v(getId(), GL_QUERY_RESULT, &value);
    return value;
}

bool Query::isResultAvailable() const {
    GLuint available = GL_FALSE;
    glGetQueryObjectuiv(getId(), GL_QUERY_RESULT_AVAILABLE, &available);
    return available == GL_TRUE;
}

void Query::writeResultTo(const Buffer& buffer, size_t offsetBytes) const {
    glGetQueryBufferObjectuiv(getId(), buffer.getId(), GL_QUERY_RESULT,
                              static_cast<GLintptr>(offsetBytes));
}

// ---- TransformFeedback ----

TransformFeedback::TransformFeedback(std::string_view label) {
    GLuint id = 0;
    glCreateTransformFeedbacks(1, &id);
    mHandle = Handle<deleteTransformFeedback>(id);
    setLabel(GL_TRANSFORM_FEEDBACK, id, label);
}

void TransformFeedback::attachBuffer(GLuint index, const Buffer& buffer, size_t offsetBytes,
                                     size_t bytes) {
    glTransformFeedbackBufferRange(getId(), index, buffer.getId(),
                                   static_cast<GLintptr>(offsetBytes),
                                   static_cast<GLsizeiptr>(bytes));
}

void TransformFeedback::begin(Primitive primitive) const {
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, getId());
    glBeginTransformFeedback(static_cast<GLenum>(primitive));
}

void TransformFeedback::end() const {
    glEndTransformFeedback();
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
}

} // namespace gl
