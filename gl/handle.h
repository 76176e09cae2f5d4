// Move-only ownership of one GL object name; the deleter is chosen by the object kind.
#pragma once

#include <glad/gl.h>

#include <string_view>
#include <utility>

namespace gl {

template <void (*Delete)(GLuint)> class Handle {
  public:
    Handle() = default;
    explicit Handle(GLuint id) : mId(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            mId = std::exchange(other.mId, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint get() const { return mId; }
    explicit operator bool() const { return mId != 0; }
    void reset() {
        if (mId) Delete(mId);
        mId = 0;
    }

  private:
    GLuint mId = 0;
};

void deleteBuffer(GLuint id);
void deleteTexture(GLuint id);
void deleteSampler(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteProgram(GLuint id);
void deleteQuery(GLuint id);
void deleteTransformFeedback(GLuint id);

// glObjectLabel for any object kind (namespace is GL_BUFFER, GL_TEXTURE, ...).
void setLabel(GLenum kind, GLuint id, std::string_view label);

} // namespace gl
