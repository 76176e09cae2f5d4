// The image environment's GLSL (lib/environment.glsl) against its CPU twin
// (scene/environment_image.cpp), whose distribution the unit tests check: for the same numbers
// the shader draws the same direction, pdf and radiance, and for the same directions it finds
// the same radiance and pdf, from the texture and GpuEnvironment the renderer uploads.
#include "support/gl_fixture.h"

#include "gl/objects.h"
#include "gl/program.h"
#include "gl/state.h"
#include "render/shader_root.h"
#include "scene/environment.h"

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace ispm::test {
namespace {

constexpr int kCount = 1000;

// Per invocation i: a sample from numbers[i].xy, and the look-up and pdf of direction[i].
constexpr const char* kShader = R"(layout(local_size_x = 64) in;
#define ENVIRONMENT_LOOKUP_ONLY 1
#include "lib/environment.glsl"
layout(std430, binding = 0) readonly buffer Numbers { vec4 numbers[]; };
layout(std430, binding = 1) writeonly buffer Out { vec4 results[]; };
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(numbers.length())) return;
    EnvironmentSample s = sampleEnvironmentImage(numbers[i].xy);
    vec3 toward = normalize(numbers[i].yzw * 2.0 - 1.0);
    results[3u * i] = vec4(s.toward, s.pdf);
    results[3u * i + 1u] = vec4(s.radiance, computeEnvironmentImagePdf(toward));
    results[3u * i + 2u] = vec4(lookUpEnvironment(toward), 0.0);
}
)";

class EnvironmentSamplingGlTest : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        // The shader's own root beside the product's lib/ and shared/ (includes resolve from the
        // root). Unique per process: ctest runs tests in parallel.
        mRoot = std::filesystem::temp_directory_path() /
                ("ispm_environment_sampling_test_" + std::to_string(::getpid()));
        std::filesystem::create_directories(mRoot);
        for (const char* folder : {"lib", "shared"}) {
            std::filesystem::create_directory_symlink(
                std::filesystem::absolute(getShaderRoot()) / folder, mRoot / folder);
        }
    }
    void TearDown() override {
        std::filesystem::remove_all(mRoot);
        GlTest::TearDown();
    }
    std::filesystem::path mRoot;
};

TEST_F(EnvironmentSamplingGlTest, ShaderSamplesAsTheCpuTwin) {
    Image map(32, 16);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (glm::vec3& p : map.pixels)
        p = glm::vec3(unit(rng), unit(rng), unit(rng)) * (unit(rng) < 0.2f ? 0.0f : 1.0f);
    map.at(20, 4) = glm::vec3(300.0f);
    const Environment environment = makeImageEnvironment(map, 1.5f, 70.0f);

    const gpu::GpuEnvironment block = makeGpuEnvironment(environment);
    const gl::Buffer blockBuffer =
        gl::Buffer::fromSpan<gpu::GpuEnvironment>("environment", std::span(&block, 1));
    gl::Texture texture =
        gl::Texture::create2D("environment image", gl::Format::RGBA32F, environment.image->width,
                              environment.image->height + 1);
    texture.uploadRgba(packEnvironmentTexels(*environment.image));
    std::vector<glm::vec4> numbers(kCount);
    for (glm::vec4& n : numbers)
        n = glm::vec4(unit(rng), unit(rng), unit(rng), unit(rng));
    const gl::Buffer numberBuffer =
        gl::Buffer::fromSpan<glm::vec4>("numbers", std::span<const glm::vec4>(numbers));
    const gl::Buffer out("results", sizeof(glm::vec4) * 3 * kCount);

    std::ofstream(mRoot / "sample.comp") << kShader;
    const gl::Program program =
        gl::Program::build(mRoot, {.label = "environment sampling",
                                   .stages = {{gl::ShaderStage::Compute, "sample.comp"}}});
    program.use();
    blockBuffer.bindBase(gl::BufferTarget::Storage, gpu::kBindingEnvironment);
    numberBuffer.bindBase(gl::BufferTarget::Storage, 0);
    out.bindBase(gl::BufferTarget::Storage, 1);
    texture.bindUnit(gpu::kUnitEnvironmentImage);
    gl::dispatchCompute((kCount + 63) / 64);
    gl::memoryBarrier(gl::Barrier::All);
    const std::vector<glm::vec4> results = out.read<glm::vec4>(3 * kCount);

    int differentTexel = 0;
    for (int i = 0; i < kCount; ++i) {
        const glm::vec4& n = numbers[size_t(i)];
        const EnvironmentSample s = sampleEnvironmentImage(environment, {n.x, n.y});
        const glm::vec4 drawn = results[size_t(3 * i)];
        const glm::vec4 values = results[size_t(3 * i + 1)];
        // float rounding apart (GPU sin and atan): the same direction and pdf.
        EXPECT_LT(glm::length(glm::vec3(drawn) - s.toward), 1e-4f) << i;
        EXPECT_NEAR(drawn.w, s.pdf, 1e-3f * s.pdf) << i;
        EXPECT_EQ(glm::vec3(values), s.radiance) << i;
        const glm::vec3 toward = glm::normalize(glm::vec3(n.y, n.z, n.w) * 2.0f - 1.0f);
        const glm::vec3 expected = evaluateEnvironment(environment, toward);
        // A direction within rounding of a texel edge may find the neighbour on one side.
        if (glm::vec3(results[size_t(3 * i + 2)]) != expected) {
            ++differentTexel;
            continue;
        }
        const float pdf = computeEnvironmentImagePdf(environment, toward);
        EXPECT_NEAR(values.w, pdf, 1e-3f * pdf + 1e-6f) << i;
    }
    EXPECT_LE(differentTexel, 2);
}

} // namespace
} // namespace ispm::test
