// The program loader: #include expansion with #line, defines, and errors that name file:line.
#include "support/gl_fixture.h"

#include "gl/gl.h"
#include "gl/objects.h"
#include "gl/program.h"

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace ispm::test {
namespace {

class ProgramTest : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        // Unique per test and process: ctest runs tests in parallel.
        mRoot = std::filesystem::temp_directory_path() /
                ("ispm_program_test_" +
                 std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                 "_" + std::to_string(::getpid()));
        std::filesystem::create_directories(mRoot / "lib");
    }
    void TearDown() override {
        std::filesystem::remove_all(mRoot);
        GlTest::TearDown();
    }
    void write(const std::string& path, const std::string& text) {
        std::ofstream(mRoot / path) << text;
    }
    std::filesystem::path mRoot;
};

TEST_F(ProgramTest, ExpandsIncludesOnceWithLineDirectives) {
    write("lib/a.glsl", "#pragma once\nfloat a() { return 1.0; }\n");
    write("lib/b.glsl", "#include \"a.glsl\"\nfloat b() { return a(); }\n");
    write("main.comp", "#include \"lib/a.glsl\"\n#include \"lib/b.glsl\"\nvoid main() {}\n");
    const gl::ExpandedSource s = gl::expandShaderSource(mRoot, "main.comp", {"FOO 3"});
    EXPECT_EQ(s.files, (std::vector<std::string>{"main.comp", "lib/a.glsl", "lib/b.glsl"}));
    EXPECT_EQ(s.text.find("#version 450 core\n#define FOO 3\n"), 0u);
    // a.glsl appears once although both main.comp and b.glsl include it.
    const size_t first = s.text.find("float a()");
    EXPECT_NE(first, std::string::npos);
    EXPECT_EQ(s.text.find("float a()", first + 1), std::string::npos);
    EXPECT_NE(s.text.find("#line 2 2\n"), std::string::npos); // back in b.glsl after its include
}

TEST_F(ProgramTest, CompileErrorNamesIncludedFileAndLine) {
    write("lib/broken.glsl",
          "float ok() { return 1.0; }\nfloat bad() { return undefinedThing; }\n");
    write("main.comp",
          "layout(local_size_x = 1) in;\n#include \"lib/broken.glsl\"\nvoid main() {}\n");
    try {
        gl::Program::build(
            mRoot, {.label = "broken", .stages = {{gl::ShaderStage::Compute, "main.comp"}}});
        FAIL() << "expected a compile error";
    } catch (const gl::Error& e) {
        EXPECT_NE(std::string(e.what()).find("lib/broken.glsl:2:"), std::string::npos) << e.what();
    }
    gl::resetDebugCounts(); // Mesa also reports the compile errors provoked here via KHR_debug
}

TEST_F(ProgramTest, MissingIncludeNamesTheIncludingFileAndLine) {
    write("main.comp",
          "layout(local_size_x = 1) in;\n\n#include \"lib/nothere.glsl\"\nvoid main() {}\n");
    try {
        gl::Program::build(
            mRoot, {.label = "missing", .stages = {{gl::ShaderStage::Compute, "main.comp"}}});
        FAIL() << "expected an include error";
    } catch (const gl::Error& e) {
        EXPECT_NE(std::string(e.what()).find("main.comp:3: cannot find included file"),
                  std::string::npos)
            << e.what();
    }
}

TEST_F(ProgramTest, DefinesSelectVariants) {
    write("main.comp",
          "layout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer B { uint v; };\n"
          "void main() { v = VALUE; }\n");
    gl::Buffer out("define out", sizeof(uint32_t));
    out.bindBase(gl::BufferTarget::Storage, 0);
    for (uint32_t value : {3u, 11u}) {
        gl::Program p =
            gl::Program::build(mRoot, {.label = "define",
                                       .stages = {{gl::ShaderStage::Compute, "main.comp"}},
                                       .defines = {"VALUE " + std::to_string(value) + "u"}});
        p.use();
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        EXPECT_EQ(out.read<uint32_t>(1)[0], value);
    }
}

} // namespace
} // namespace ispm::test
