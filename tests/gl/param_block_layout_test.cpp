// The parameter blocks that cross to the GPU as std140 uniform blocks, checked on both sides: each
// named field's offset as the GL lays the block out (a shader declaring it from the shared header
// as the passes do) against offsetof in C++, and the block's size against sizeof. C++ maps vec3
// to a 12-byte glm::vec3, so a field after one lands where std140 puts it only if the header
// pairs it with a scalar or padding: this catches a header that does not.
#include "support/gl_fixture.h"

#include "gl/program.h"
#include "render/shader_root.h"

#include <shared/debug_data.h>
#include <shared/gather_data.h>
#include <shared/importance_data.h>
#include <shared/light_trace_data.h>
#include <shared/photon_data.h>
#include <shared/post_data.h>
#include <shared/scene_data.h>
#include <shared/specular_data.h>
#include <shared/viewer_data.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace ispm::test {
namespace {

// One field as GLSL names it below the block's instance (`params.`) and where C++ puts it.
struct Field {
    std::string glslName; // "lightCount", "lights[0]", "travel.radiusMinM"
    size_t offset;
};

struct Block {
    std::string type; // the struct's name in both languages
    size_t size;
    // Every field but padding (the test shader reads each). An array is named by its first
    // element (the GL's name for it); the block's size checks its stride.
    std::vector<Field> fields;
};

#define ISPM_FIELD(T, field)                                                                       \
    Field {                                                                                        \
#field, offsetof(gpu::T, field)                                                            \
    }

std::vector<Block> getBlocks() {
    return {
        {"FrameConstants",
         sizeof(gpu::FrameConstants),
         {ISPM_FIELD(FrameConstants, clipFromWorld), ISPM_FIELD(FrameConstants, worldFromClip),
          ISPM_FIELD(FrameConstants, eyeOffsetFromClip), ISPM_FIELD(FrameConstants, cameraPosW),
          ISPM_FIELD(FrameConstants, lightCount), ISPM_FIELD(FrameConstants, backgroundRadiance),
          ISPM_FIELD(FrameConstants, lightViewCount), ISPM_FIELD(FrameConstants, imageSizePx),
          ISPM_FIELD(FrameConstants, inverseImageSizePx), ISPM_FIELD(FrameConstants, seed),
          ISPM_FIELD(FrameConstants, tonemapOperator), ISPM_FIELD(FrameConstants, shadowBiasTexels),
          ISPM_FIELD(FrameConstants, lightResolutionPx),
          ISPM_FIELD(FrameConstants, adaptationWeight), ISPM_FIELD(FrameConstants, exposureScale),
          ISPM_FIELD(FrameConstants, inverseGamma), ISPM_FIELD(FrameConstants, luminanceMax),
          ISPM_FIELD(FrameConstants, specularTraceMinExponent)}},
        {"AccumulateParams",
         sizeof(gpu::AccumulateParams),
         {ISPM_FIELD(AccumulateParams, previousClipFromWorld),
          ISPM_FIELD(AccumulateParams, directWeight),
          ISPM_FIELD(AccumulateParams, historyCapFrames), ISPM_FIELD(AccumulateParams, moved)}},
        {"DirectParams",
         sizeof(gpu::DirectParams),
         {ISPM_FIELD(DirectParams, lightCount), ISPM_FIELD(DirectParams, firstDraw),
          ISPM_FIELD(DirectParams, rayFloorM),
          Field{"lights[0]", offsetof(gpu::DirectParams, lights)}}},
        {"DirectEdgeParams",
         sizeof(gpu::DirectEdgeParams),
         {ISPM_FIELD(DirectEdgeParams, samplesPerPixel), ISPM_FIELD(DirectEdgeParams, rayFloorM)}},
        {"FilterParams",
         sizeof(gpu::FilterParams),
         {ISPM_FIELD(FilterParams, stepPx), ISPM_FIELD(FilterParams, modulate),
          ISPM_FIELD(FilterParams, pixelsPerBufferPx)}},
        {"GBufferParams",
         sizeof(gpu::GBufferParams),
         {ISPM_FIELD(GBufferParams, clipFromWorld),
          ISPM_FIELD(GBufferParams, previousClipFromWorld), ISPM_FIELD(GBufferParams, eye),
          ISPM_FIELD(GBufferParams, halfTargetSizePx), ISPM_FIELD(GBufferParams, jitterMotionPx),
          ISPM_FIELD(GBufferParams, instance)}},
        {"ReferenceParams",
         sizeof(gpu::ReferenceParams),
         {ISPM_FIELD(ReferenceParams, sampleIndex), ISPM_FIELD(ReferenceParams, bounces),
          ISPM_FIELD(ReferenceParams, seed), ISPM_FIELD(ReferenceParams, rayOffsetM)}},
        {"PrepareParams",
         sizeof(gpu::PrepareParams),
         {ISPM_FIELD(PrepareParams, resultCapacity), ISPM_FIELD(PrepareParams, bounceCapacity),
          ISPM_FIELD(PrepareParams, stage), ISPM_FIELD(PrepareParams, splatDraws),
          ISPM_FIELD(PrepareParams, splatIndexCount), ISPM_FIELD(PrepareParams, photonsPerLane)}},
        {"TraceParams",
         sizeof(gpu::TraceParams),
         {ISPM_FIELD(TraceParams, bounces), ISPM_FIELD(TraceParams, seed),
          ISPM_FIELD(TraceParams, rngGenerator), ISPM_FIELD(TraceParams, rngMode),
          ISPM_FIELD(TraceParams, rayOffsetM), ISPM_FIELD(TraceParams, slice),
          ISPM_FIELD(TraceParams, slices)}},
        {"EmitParams",
         sizeof(gpu::EmitParams),
         {ISPM_FIELD(EmitParams, lightView), ISPM_FIELD(EmitParams, firstPhoton),
          ISPM_FIELD(EmitParams, gridPhotons), ISPM_FIELD(EmitParams, seed),
          ISPM_FIELD(EmitParams, rngGenerator), ISPM_FIELD(EmitParams, lightResolutionPx),
          ISPM_FIELD(EmitParams, firstBounce)}},
        {"SplatParams",
         sizeof(gpu::SplatParams),
         {ISPM_FIELD(SplatParams, clipLines), ISPM_FIELD(SplatParams, shape),
          ISPM_FIELD(SplatParams, draw), ISPM_FIELD(SplatParams, drawCount),
          ISPM_FIELD(SplatParams, squash), ISPM_FIELD(SplatParams, pixelsPerBufferPx),
          ISPM_FIELD(SplatParams, targetOffsetPx), ISPM_FIELD(SplatParams, photons),
          ISPM_FIELD(SplatParams, discList)}},
        {"OrderParams",
         sizeof(gpu::OrderParams),
         {ISPM_FIELD(OrderParams, loW), ISPM_FIELD(OrderParams, countsAt),
          ISPM_FIELD(OrderParams, cellsPerM), ISPM_FIELD(OrderParams, orderAt)}},
        {"DensityParams",
         sizeof(gpu::DensityParams),
         {ISPM_FIELD(DensityParams, finestCellM),
          ISPM_FIELD(DensityParams, neighbours),
          ISPM_FIELD(DensityParams, radiusMinM),
          ISPM_FIELD(DensityParams, radiusMaxM),
          ISPM_FIELD(DensityParams, radiusScale),
          ISPM_FIELD(DensityParams, rayOffsetM),
          ISPM_FIELD(DensityParams, travelRadiusFactor),
          ISPM_FIELD(DensityParams, mergeCellPerRadius),
          ISPM_FIELD(DensityParams, stage),
          ISPM_FIELD(DensityParams, slotMask),
          ISPM_FIELD(DensityParams, spreadStrong),
          ISPM_FIELD(DensityParams, radiusMode),
          ISPM_FIELD(DensityParams, travel.radiusMinM),
          ISPM_FIELD(DensityParams, travel.radiusMaxM),
          ISPM_FIELD(DensityParams, travel.distMinM),
          ISPM_FIELD(DensityParams, travel.distMaxM),
          ISPM_FIELD(DensityParams, slice),
          ISPM_FIELD(DensityParams, slices),
          ISPM_FIELD(DensityParams, orderAt),
          ISPM_FIELD(DensityParams, causticListAt),
          ISPM_FIELD(DensityParams, squash),
          ISPM_FIELD(DensityParams, discListAt)}},
        {"ImportanceParams",
         sizeof(gpu::ImportanceParams),
         {ISPM_FIELD(ImportanceParams, gatherSamples), ISPM_FIELD(ImportanceParams, lightViewCount),
          ISPM_FIELD(ImportanceParams, seed), ISPM_FIELD(ImportanceParams, importanceShare),
          ISPM_FIELD(ImportanceParams, visibleWeight), ISPM_FIELD(ImportanceParams, bounceWeight),
          ISPM_FIELD(ImportanceParams, rayOffsetM), ISPM_FIELD(ImportanceParams, historyWeight),
          ISPM_FIELD(ImportanceParams, hitScale), ISPM_FIELD(ImportanceParams, unlitWeight)}},
        {"PostParams",
         sizeof(gpu::PostParams),
         {ISPM_FIELD(PostParams, bloomThreshold), ISPM_FIELD(PostParams, bloomIntensity),
          ISPM_FIELD(PostParams, bloomRadiusPx), ISPM_FIELD(PostParams, bloomSigmaPx),
          ISPM_FIELD(PostParams, apertureM), ISPM_FIELD(PostParams, inverseFocusPerM),
          ISPM_FIELD(PostParams, pixelsPerRadian), ISPM_FIELD(PostParams, focusAtCentre),
          ISPM_FIELD(PostParams, viewAxisW), ISPM_FIELD(PostParams, shutter),
          ISPM_FIELD(PostParams, blurAxis), ISPM_FIELD(PostParams, addsSource)}},
        {"SpecularParams",
         sizeof(gpu::SpecularParams),
         {ISPM_FIELD(SpecularParams, levels), ISPM_FIELD(SpecularParams, rayFloorM),
          ISPM_FIELD(SpecularParams, reprojectionTolerance),
          ISPM_FIELD(SpecularParams, pixelAngleRad)}},
        {"GatherParams",
         sizeof(gpu::GatherParams),
         {ISPM_FIELD(GatherParams, tiles), ISPM_FIELD(GatherParams, tileCount),
          ISPM_FIELD(GatherParams, clipLines), ISPM_FIELD(GatherParams, bufferSizePx),
          ISPM_FIELD(GatherParams, pixelsPerBufferPx), ISPM_FIELD(GatherParams, photons),
          ISPM_FIELD(GatherParams, squash)}},
        {"LightTraceParams",
         sizeof(gpu::LightTraceParams),
         {ISPM_FIELD(LightTraceParams, sampleIndex), ISPM_FIELD(LightTraceParams, bounces),
          ISPM_FIELD(LightTraceParams, seed), ISPM_FIELD(LightTraceParams, pathCount),
          ISPM_FIELD(LightTraceParams, rayFloorM), ISPM_FIELD(LightTraceParams, pixelAreaM2),
          ISPM_FIELD(LightTraceParams, cameraAxisW), ISPM_FIELD(LightTraceParams, sceneCentreW),
          ISPM_FIELD(LightTraceParams, sceneRadiusM)}},
        {"BlitParams",
         sizeof(gpu::BlitParams),
         {ISPM_FIELD(BlitParams, regionOriginPx), ISPM_FIELD(BlitParams, regionSizePx),
          ISPM_FIELD(BlitParams, scale), ISPM_FIELD(BlitParams, bias),
          ISPM_FIELD(BlitParams, inverseGamma), ISPM_FIELD(BlitParams, layer),
          ISPM_FIELD(BlitParams, masked)}},
        {"ReferenceViewParams",
         sizeof(gpu::ReferenceViewParams),
         {ISPM_FIELD(ReferenceViewParams, regionOriginPx),
          ISPM_FIELD(ReferenceViewParams, regionSizePx), ISPM_FIELD(ReferenceViewParams, scale),
          ISPM_FIELD(ReferenceViewParams, inverseGamma),
          ISPM_FIELD(ReferenceViewParams, heatMapMax), ISPM_FIELD(ReferenceViewParams, mode)}},
        {"TraceRaysParams", sizeof(gpu::TraceRaysParams), {ISPM_FIELD(TraceRaysParams, rayCount)}},
        {"PhotonPointsParams",
         sizeof(gpu::PhotonPointsParams),
         {ISPM_FIELD(PhotonPointsParams, tint), ISPM_FIELD(PhotonPointsParams, pointSizePx),
          ISPM_FIELD(PhotonPointsParams, powerScale), ISPM_FIELD(PhotonPointsParams, inverseGamma),
          ISPM_FIELD(PhotonPointsParams, colouring)}},
        // A storage buffer's element (std430), checked here as std140: for two vec2 and a vec4
        // the two rules place every field alike.
        {"GpuVertexAttributes",
         sizeof(gpu::GpuVertexAttributes),
         {ISPM_FIELD(GpuVertexAttributes, texcoord), ISPM_FIELD(GpuVertexAttributes, normal),
          ISPM_FIELD(GpuVertexAttributes, tangent)}},
    };
}

#undef ISPM_FIELD

// A compute shader that declares `block` as the passes do (a std140 block holding one instance
// named params, its type from the shared headers) and reads every listed field, so that the
// linker keeps each one active and reports its offset. use() folds any field's type to a float.
std::string makeShader(const Block& block) {
    std::string text = R"(layout(local_size_x = 1) in;
#include "shared/scene_data.h"
#include "shared/photon_data.h"
#include "shared/importance_data.h"
#include "shared/post_data.h"
#include "shared/specular_data.h"
#include "shared/gather_data.h"
#include "shared/light_trace_data.h"
#include "shared/viewer_data.h"
#include "shared/debug_data.h"
float use(float v) { return v; }
float use(uint v) { return float(v); }
float use(int v) { return float(v); }
float use(vec2 v) { return v.x + v.y; }
float use(uvec2 v) { return float(v.x + v.y); }
float use(ivec2 v) { return float(v.x + v.y); }
float use(vec3 v) { return v.x + v.y + v.z; }
float use(vec4 v) { return v.x + v.y + v.z + v.w; }
float use(uvec4 v) { return float(v.x + v.y + v.z + v.w); }
float use(mat4 m) { return use(m[0]) + use(m[3]); }
layout(std140, binding = kBindingPassParams) uniform Block { )";
    text += block.type + " params; };\n";
    text += "layout(std430, binding = 0) writeonly buffer Sink { float sink; };\n";
    text += "void main() {\n    float sum = 0.0;\n";
    for (const Field& f : block.fields)
        text += "    sum += use(params." + f.glslName + ");\n";
    text += "    sink = sum;\n}\n";
    return text;
}

class ParamBlockLayoutTest : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        // The shader's own root beside the product's shared headers (the loader resolves
        // includes from the root). Unique per process: ctest runs tests in parallel.
        mRoot = std::filesystem::temp_directory_path() /
                ("ispm_param_block_layout_test_" + std::to_string(::getpid()));
        std::filesystem::create_directories(mRoot);
        std::filesystem::create_directory_symlink(
            std::filesystem::absolute(getShaderRoot()) / "shared", mRoot / "shared");
    }
    void TearDown() override {
        std::filesystem::remove_all(mRoot);
        GlTest::TearDown();
    }
    std::filesystem::path mRoot;
};

TEST_F(ParamBlockLayoutTest, FieldOffsetsMatchOnBothSides) {
    for (const Block& block : getBlocks()) {
        SCOPED_TRACE(block.type);
        const std::string path = block.type + ".comp";
        std::ofstream(mRoot / path) << makeShader(block);
        const gl::Program program = gl::Program::build(
            mRoot, {.label = block.type + " layout", .stages = {{gl::ShaderStage::Compute, path}}});
        EXPECT_EQ(program.getUniformBlockSize("Block"), block.size);
        for (const Field& f : block.fields)
            EXPECT_EQ(program.getUniformOffset("params." + f.glslName), f.offset) << f.glslName;
    }
}

// The check itself: a C++ struct whose vec3 is followed by a vec3 (no scalar in the 4th slot)
// lies 4 bytes short of std140 from there on, and the test's query sees it.
TEST_F(ParamBlockLayoutTest, QueryFindsAMisplacedField) {
    struct Misplaced {
        gpu::vec3 a;
        gpu::vec3 b; // std140: at 16
    };
    std::ofstream(mRoot / "misplaced.comp") << R"(layout(local_size_x = 1) in;
struct Misplaced { vec3 a; vec3 b; };
layout(std140, binding = 0) uniform Block { Misplaced params; };
layout(std430, binding = 0) writeonly buffer Sink { float sink; };
void main() { sink = params.a.x + params.b.x; }
)";
    const gl::Program program =
        gl::Program::build(mRoot, {.label = "misplaced layout",
                                   .stages = {{gl::ShaderStage::Compute, "misplaced.comp"}}});
    EXPECT_EQ(program.getUniformOffset("params.a"), offsetof(Misplaced, a));
    EXPECT_NE(program.getUniformOffset("params.b"), offsetof(Misplaced, b));
    EXPECT_EQ(program.getUniformOffset("params.nothere"), std::nullopt);
}

} // namespace
} // namespace ispm::test
