// The headless context: 4.5 core, a named path, debug output that really reports errors.
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
