// KHR_debug callback: one log line per error or warning (every message with ISPM_GL_DEBUG=1),
// counted by severity/type.
#include "gl/debug.h"

#include "gl/gl.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <mutex>

namespace gl {
namespace {

constexpr size_t kRecentErrorCount = 16; // enough context for a failing test's report

std::atomic<uint64_t> gErrors{0};
std::atomic<uint64_t> gWarnings{0};
std::atomic<uint64_t> gOther{0};
std::atomic<bool> gVerbose{false};
std::mutex gRecentMutex;
std::deque<std::string> gRecentErrors;

const char* describeType(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR:
        return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
        return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
        return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY:
        return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
        return "performance";
    case GL_DEBUG_TYPE_MARKER:
        return "marker";
    case GL_DEBUG_TYPE_PUSH_GROUP:
        return "push group";
    case GL_DEBUG_TYPE_POP_GROUP:
        return "pop group";
    default:
        return "other";
    }
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                               GLsizei length, const GLchar* message, const void* user) {
    (void)source;
    (void)user;
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
    const std::string text(message, length < 0 ? std::char_traits<char>::length(message)
                                               : static_cast<size_t>(length));
    const bool isError = type == GL_DEBUG_TYPE_ERROR;
    const bool isWarning =
        type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR || type == GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR ||
        type == GL_DEBUG_TYPE_PORTABILITY ||
        (type == GL_DEBUG_TYPE_PERFORMANCE && severity != GL_DEBUG_SEVERITY_NOTIFICATION);
    if (isError) {
        ++gErrors;
        std::lock_guard lock(gRecentMutex);
        gRecentErrors.push_back(text);
        if (gRecentErrors.size() > kRecentErrorCount) gRecentErrors.pop_front();
    } else if (isWarning) {
        ++gWarnings;
    } else {
        ++gOther;
    }
    // A performance message describes the driver's own choices (NVIDIA's: where it keeps a
    // buffer, a shader rebuilt for a state): counted, printed when verbose.
    const bool isPerformance = type == GL_DEBUG_TYPE_PERFORMANCE;
    if (isError || (isWarning && !isPerformance) || gVerbose) {
        std::fprintf(stderr, "[gl %s %u] %s\n", describeType(type), id, text.c_str());
    }
}

} // namespace

void installDebugOutput() {
    if (const char* verbose = std::getenv("ISPM_GL_DEBUG"); verbose && *verbose)
        gVerbose = std::string_view(verbose) != "0";
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

DebugCounts getDebugCounts() {
    return {gErrors.load(), gWarnings.load(), gOther.load()};
}

void resetDebugCounts() {
    gErrors = 0;
    gWarnings = 0;
    gOther = 0;
    std::lock_guard lock(gRecentMutex);
    gRecentErrors.clear();
}

std::vector<std::string> getRecentDebugErrors() {
    std::lock_guard lock(gRecentMutex);
    return {gRecentErrors.begin(), gRecentErrors.end()};
}

void setDebugVerbose(bool verbose) {
    gVerbose = verbose;
}

void muteShaderCompilerMessages() {
    glDebugMessageControl(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr,
                          GL_FALSE);
}

DebugGroup::DebugGroup(std::string_view name) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()),
                     name.data());
}

DebugGroup::~DebugGroup() {
    glPopDebugGroup();
}

} // namespace gl
