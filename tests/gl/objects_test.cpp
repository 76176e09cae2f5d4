// Every RAII object kind: creation, labels, move semantics, deletion, and the data each holds.
#include "support/gl_fixture.h"

#include "gl/gl.h"
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/state.h"

#include <filesystem>
#include <fstream>
#include <numeric>

#include <unistd.h>

namespace ispm::test {
namespace {

class ObjectsTest : public GlTest {};

std::string getLabel(GLenum kind, GLuint id) {
    constexpr int kMaxLabel = 256;
    char label[kMaxLabel] = {};
    GLsizei length = 0;
    glGetObjectLabel(kind, id, kMaxLabel, &length, label);
    return std::string(label, static_cast<size_t>(length));
}

TEST_F(ObjectsTest, BufferRoundTripMoveAndDelete) {
    std::vector<uint32_t> data(1000);
    std::iota(data.begin(), data.end(), 7u);
    gl::Buffer a = gl::Buffer::fromSpan<uint32_t>("test buffer", data);
    EXPECT_EQ(getLabel(GL_BUFFER, a.getId()), "test buffer");
    EXPECT_EQ(a.read<uint32_t>(data.size()), data);
    const GLuint id = a.getId();
    gl::Buffer b = std::move(a);
    EXPECT_EQ(a.getId(), 0u);
    EXPECT_EQ(b.getId(), id);
    b.clearToZero();
    EXPECT_EQ(b.read<uint32_t>(3), std::vector<uint32_t>(3, 0u));
    b = gl::Buffer();
    EXPECT_FALSE(glIsBuffer(id));
}

TEST_F(ObjectsTest, SmallReadsThroughTheStagingCopyMatchLargeOnes) {
    // Reads of up to kStagedReadBytes go through a copy; the rest straight from the buffer.
    constexpr size_t kWords = gl::Buffer::kStagedReadBytes / sizeof(uint32_t) * 2;
    std::vector<uint32_t> data(kWords);
    std::iota(data.begin(), data.end(), 11u);
    const gl::Buffer buffer = gl::Buffer::fromSpan<uint32_t>("staged reads", data);
    EXPECT_EQ(buffer.read<uint32_t>(kWords), data); // large: direct
    // Offsets, and a size past the staging copy's first (it grows).
    EXPECT_EQ(buffer.read<uint32_t>(2, 40), std::vector<uint32_t>({21u, 22u}));
    const std::vector<uint32_t> staged = buffer.read<uint32_t>(1000, 400);
    EXPECT_EQ(staged, std::vector<uint32_t>(data.begin() + 100, data.begin() + 1100));
    // A read sees what the GPU wrote after the last one.
    buffer.clearRangeToZero(40, 8);
    EXPECT_EQ(buffer.read<uint32_t>(3, 36), std::vector<uint32_t>({20u, 0u, 0u}));
}

TEST_F(ObjectsTest, TextureUploadReadAndArrays) {
    constexpr int kW = 7; // awkward sizes catch row-stride mistakes
    constexpr int kH = 3;
    gl::Texture t = gl::Texture::create2D("test texture", gl::Format::RGBA32F, kW, kH);
    std::vector<glm::vec4> texels(kW * kH);
    for (size_t i = 0; i < texels.size(); ++i)
        texels[i] = glm::vec4(float(i), -float(i), 0.5f, 1.0f);
    t.uploadRgba(texels);
    EXPECT_EQ(t.readRgba(), texels);
    EXPECT_EQ(getLabel(GL_TEXTURE, t.getId()), "test texture");

    gl::Texture arr = gl::Texture::create2DArray("test array", gl::Format::RGBA32F, kW, kH, 6);
    arr.uploadRgba(texels, 4);
    EXPECT_EQ(arr.readRgba(4), texels);
    const GLuint id = arr.getId();
    { gl::Texture moved = std::move(arr); }
    EXPECT_FALSE(glIsTexture(id));
}

TEST_F(ObjectsTest, SamplerVertexArrayQueryTransformFeedbackLabels) {
    gl::Sampler sampler("test sampler", gl::Filter::Nearest, gl::Wrap::ClampToEdge);
    gl::VertexArray vao("test vao");
    gl::Query query("test query", gl::QueryTarget::PrimitivesWritten);
    gl::TransformFeedback feedback("test feedback");
    EXPECT_EQ(getLabel(GL_SAMPLER, sampler.getId()), "test sampler");
    EXPECT_EQ(getLabel(GL_VERTEX_ARRAY, vao.getId()), "test vao");
    EXPECT_EQ(getLabel(GL_QUERY, query.getId()), "test query");
    EXPECT_EQ(getLabel(GL_TRANSFORM_FEEDBACK, feedback.getId()), "test feedback");
    const GLuint samplerId = sampler.getId();
    sampler = gl::Sampler();
    EXPECT_FALSE(glIsSampler(samplerId));
}

TEST_F(ObjectsTest, FramebufferClearsAttachments) {
    gl::Texture color = gl::Texture::create2D("fb colour", gl::Format::RGBA32F, 5, 4);
    gl::Texture depth = gl::Texture::create2D("fb depth", gl::Format::Depth32F, 5, 4);
    gl::Framebuffer fb("test framebuffer");
    fb.attachColor(0, color);
    fb.attachDepth(depth);
    fb.setDrawBufferCount(1);
    fb.checkComplete();
    fb.clearColor(0, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
    fb.clearDepth(0.5f);
    for (const glm::vec4& c : color.readRgba())
        EXPECT_EQ(c, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
    for (float d : depth.readDepth())
        EXPECT_EQ(d, 0.5f);
    gl::Framebuffer incomplete("incomplete framebuffer");
    EXPECT_THROW(incomplete.checkComplete(), gl::Error);
}

// Transform feedback through a geometry shader into a buffer, the count written by a query into
// another buffer on the GPU: the mechanism photon emission stands on.
TEST_F(ObjectsTest, GeometryShaderTransformFeedbackWithQueryBuffer) {
    const std::filesystem::path root =
        std::filesystem::temp_directory_path() / ("ispm_tf_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(root);
    std::ofstream(root / "tf.vert") << "out int vIndex;\nvoid main() { vIndex = gl_VertexID; }\n";
    std::ofstream(root / "tf.geom")
        << "layout(points) in;\nlayout(points, max_vertices = 1) out;\nin int vIndex[];\n"
           "out float outValue;\n"
           "void main() { if (vIndex[0] % 3 == 0) { outValue = float(vIndex[0]); EmitVertex(); } "
           "}\n";
    gl::Program program = gl::Program::build(
        root,
        {.label = "tf test",
         .stages = {{gl::ShaderStage::Vertex, "tf.vert"}, {gl::ShaderStage::Geometry, "tf.geom"}},
         .feedbackVaryings = {"outValue"}});
    constexpr int kPoints = 1000;
    constexpr int kExpected = (kPoints + 2) / 3; // indices 0, 3, 6, ...
    gl::Buffer captured("tf capture", kPoints * sizeof(float));
    gl::Buffer count("tf count", sizeof(uint32_t));
    gl::TransformFeedback feedback("tf object");
    feedback.attachBuffer(0, captured, 0, captured.getSize());
    gl::Query written("tf written", gl::QueryTarget::PrimitivesWritten);
    gl::Framebuffer fb("tf framebuffer");
    fb.setDefaultSize(1, 1); // framebuffer 0 does nothing in a headless context
    fb.bind();
    gl::VertexArray vao("tf vao");
    vao.bind();
    program.use();
    gl::applyState({.rasterizerDiscard = true});
    written.begin();
    feedback.begin(gl::Primitive::Points);
    gl::drawArrays(gl::Primitive::Points, 0, kPoints);
    feedback.end();
    written.end();
    gl::applyState({});
    written.writeResultTo(count, 0);
    gl::memoryBarrier(gl::Barrier::QueryBuffer | gl::Barrier::BufferUpdate);
    EXPECT_EQ(count.read<uint32_t>(1)[0], static_cast<uint32_t>(kExpected));
    const std::vector<float> values = captured.read<float>(kExpected);
    for (int i = 0; i < kExpected; ++i)
        EXPECT_EQ(values[static_cast<size_t>(i)], float(3 * i));
    std::filesystem::remove_all(root);
}

} // namespace
} // namespace ispm::test
