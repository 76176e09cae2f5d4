// The headless context: 4.5 core, a named path, debug output that really reports errors and
// keeps the driver's performance notes quiet unless asked.
#include "support/gl_fixture.h"

#include "gl/gl.h"

#include <cstdlib>

namespace ispm::test {
namespace {

class ContextTest : public GlTest {};

TEST_F(ContextTest, IsOpenGl45Core) {
    GLint major = 0;
    GLint minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    EXPECT_GE(major * 10 + minor, 45);
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    const gl::ContextInfo& info = getTestContext().getInfo();
    EXPECT_FALSE(info.renderer.empty());
    EXPECT_FALSE(info.version.empty());
}

TEST_F(ContextTest, DebugOutputCountsErrors) {
    gl::resetDebugCounts();
    glBindBuffer(GL_ARRAY_BUFFER, 123456); // not a name from glGen/glCreate: an error
    EXPECT_GE(gl::getDebugCounts().errors, 1u);
    EXPECT_FALSE(gl::getRecentDebugErrors().empty());
    gl::resetDebugCounts(); // the error was provoked on purpose
}

TEST_F(ContextTest, PerformanceMessagesAreCountedAndPrintedWhenVerbose) {
    // NVIDIA's driver reports where it keeps each buffer as a medium-severity performance
    // message: counted as a warning, printed only with ISPM_GL_DEBUG=1 (setDebugVerbose), while
    // a warning about ispm's own use of GL is always printed.
    const auto insert = [](GLenum type, const char* text) {
        glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, type, 1, GL_DEBUG_SEVERITY_MEDIUM, -1,
                             text);
    };
    const uint64_t before = gl::getDebugCounts().warnings;
    testing::internal::CaptureStderr();
    insert(GL_DEBUG_TYPE_PERFORMANCE, "driver note one");
    std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_EQ(gl::getDebugCounts().warnings, before + 1);
    EXPECT_EQ(printed.find("driver note one"), std::string::npos);

    gl::setDebugVerbose(true);
    testing::internal::CaptureStderr();
    insert(GL_DEBUG_TYPE_PERFORMANCE, "driver note two");
    printed = testing::internal::GetCapturedStderr();
    gl::setDebugVerbose(false);
    EXPECT_NE(printed.find("driver note two"), std::string::npos);

    testing::internal::CaptureStderr();
    insert(GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR, "undefined use");
    printed = testing::internal::GetCapturedStderr();
    EXPECT_NE(printed.find("undefined use"), std::string::npos);
    EXPECT_EQ(gl::getDebugCounts().warnings, before + 3);
}

TEST(ContextPaths, ForcedPathsWorkOrFailClearly) {
    // Each forced path either gives a 4.5 context or throws gl::Error naming the path; llvmpipe
    // provides all three, so on this test renderer each must succeed.
    for (const char* path : {"egl-device", "egl-surfaceless", "osmesa"}) {
        ::setenv("ISPM_GL", path, 1);
        std::unique_ptr<gl::Context> context;
        ASSERT_NO_THROW(context = gl::createHeadlessContext()) << path;
        EXPECT_STREQ(gl::getContextPathName(context->getInfo().path), path);
        GLint major = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        EXPECT_EQ(major, 4) << path;
    }
    ::setenv("ISPM_GL", "bogus", 1);
    EXPECT_THROW(gl::createHeadlessContext(), gl::Error);
    ::unsetenv("ISPM_GL");
    getTestContext().makeCurrent();
}

} // namespace
} // namespace ispm::test
