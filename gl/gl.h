// The one include for OpenGL in ispm: glad's GL 4.5 core loader plus the project's error helpers.
#pragma once

#include <glad/gl.h>

#include <stdexcept>
#include <string>

namespace gl {

// Runtime failures of the GL layer (context creation, shader compile, I/O): carry context.
class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

} // namespace gl
