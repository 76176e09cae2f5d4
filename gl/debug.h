// KHR_debug plumbing: messages go to the log and are counted, so tests can fail on any GL error,
// and debug groups name each pass in captures and logs.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gl {

struct DebugCounts {
    uint64_t errors = 0;
    uint64_t warnings = 0; // deprecated/undefined behaviour, portability, performance
    uint64_t other = 0;
};

// Enables synchronous debug output on the current context and installs the logging callback.
void installDebugOutput();
DebugCounts getDebugCounts();
void resetDebugCounts();
// The last error messages (bounded), for test failure reports.
std::vector<std::string> getRecentDebugErrors();
// Logs notifications and performance messages too (off by default: llvmpipe is chatty about
// shader compiles, NVIDIA about where it keeps buffers); ISPM_GL_DEBUG=1 sets it when the
// debug output is installed.
void setDebugVerbose(bool verbose);

// Drops the shader compiler's messages until the enclosing DebugGroup ends (which restores the
// message filter it started with).
void muteShaderCompilerMessages();

// RAII debug group: glPush/PopDebugGroup around a scope.
class DebugGroup {
  public:
    explicit DebugGroup(std::string_view name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

} // namespace gl
