// The shared context is created on first use and lives until the process exits.
#include "support/gl_fixture.h"

#include <string>

namespace ispm::test {

gl::Context& getTestContext() {
    static std::unique_ptr<gl::Context> context = gl::createHeadlessContext();
    return *context;
}

void GlTest::SetUp() {
    getTestContext().makeCurrent();
    gl::resetDebugCounts();
}

void GlTest::TearDown() {
    const gl::DebugCounts counts = gl::getDebugCounts();
    std::string messages;
    for (const std::string& m : gl::getRecentDebugErrors())
        messages += "\n  " + m;
    EXPECT_EQ(counts.errors, 0u) << "KHR_debug reported errors:" << messages;
}

} // namespace ispm::test
