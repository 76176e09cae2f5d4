// The GPU traversal (shaders/lib/bvh.glsl through shaders/debug/trace_rays.comp) against the CPU
// traversal over the same BvhScene arrays: per ray the same hit or miss, triangle, instance and
// distance, on a two-instance box city and on a scene the rays miss.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"

#include "bvh/bvh_traversal.h"
#include "core/strings.h"
#include "gl/gl.h"
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"
#include "scene/box_city.h"

#include <shared/debug_data.h>
#include <shared/scene_data.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace ispm::test {
namespace {

// GpuScene's light G-buffer size; these scenes have no lights, so any valid size does.
constexpr int kLightResolution = 64;
// Far enough for any ray of these scenes, and finite as the product's tracer passes it.
constexpr float kLongRayM = 1e30f;

struct GpuHit {
    bool found = false;
    uint32_t triangle = 0;
    uint32_t instance = 0;
    float t = 0.0f;
};

gl::Program buildTraceRaysProgram() {
    return gl::Program::build(getShaderRoot(),
                              {.label = "debug trace rays",
                               .stages = {{gl::ShaderStage::Compute, "debug/trace_rays.comp"}}});
}

std::vector<GpuHit> traceOnGpu(const GpuScene& scene, std::span<const Ray> rays) {
    std::vector<gpu::DebugRay> debugRays;
    debugRays.reserve(rays.size());
    for (const Ray& r : rays) {
        debugRays.push_back({glm::vec4(r.origin, r.tMax), glm::vec4(r.direction, 0.0f)});
    }
    const auto rayBuffer = gl::Buffer::fromSpan<gpu::DebugRay>("debug rays", debugRays);
    const gl::Buffer resultBuffer("debug ray results", rays.size() * sizeof(glm::uvec4));
    const gl::Program program = buildTraceRaysProgram();
    scene.bind();
    rayBuffer.bindBase(gl::BufferTarget::Storage, gpu::kBindingDebugRays);
    resultBuffer.bindBase(gl::BufferTarget::Storage, gpu::kBindingDebugResults);
    program.use();
    const auto rayCount = static_cast<GLuint>(rays.size());
    const gpu::TraceRaysParams params{.rayCount = rayCount};
    const gl::Buffer paramBuffer("debug trace rays parameters", sizeof(params));
    paramBuffer.upload(0, sizeof(params), &params);
    paramBuffer.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    gl::dispatchCompute((rayCount + gpu::kTraceRaysGroupSize - 1) / gpu::kTraceRaysGroupSize);
    gl::memoryBarrier(gl::Barrier::BufferUpdate); // the read-back follows a shader write
    std::vector<GpuHit> hits;
    hits.reserve(rays.size());
    for (const glm::uvec4& r : resultBuffer.read<glm::uvec4>(rays.size())) {
        hits.push_back({r.x != 0u, r.y, r.z, std::bit_cast<float>(r.w)});
    }
    return hits;
}

// Uniform in [0, 1) from the top 24 bits: std:: distributions differ between standard
// libraries, and these rays must be the same everywhere.
float drawUniform(std::mt19937& rng) {
    constexpr int kMantissaBits = 24;
    return static_cast<float>(rng() >> (32 - kMantissaBits)) * 0x1p-24f;
}

glm::vec3 drawDirection(std::mt19937& rng) {
    const float z = 1.0f - 2.0f * drawUniform(rng);
    const float phi = 2.0f * glm::pi<float>() * drawUniform(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return glm::normalize(glm::vec3(r * std::cos(phi), r * std::sin(phi), z));
}

// The distance at which the ray meets one given triangle of one instance, if it does, so that a
// GPU hit on another triangle than the CPU's can be checked rather than taken on trust. Edges get
// a little slack: such hits are exactly the ones rounding sends either way.
std::optional<float> intersectClaimedTriangle(const BvhScene& bvh, const Scene& scene,
                                              const Ray& ray, uint32_t instance,
                                              uint32_t triangle) {
    constexpr float kBarycentricSlack = 1e-4f; // ~1000x the rounding of a barycentric in [0, 1]
    if (instance >= scene.instances.size()) return std::nullopt;
    const uint32_t meshIndex = scene.instances[instance].meshIndex;
    const Mesh& mesh = scene.meshes[meshIndex];
    const uint32_t local = triangle - bvh.meshFirstTriangles[meshIndex];
    if (triangle < bvh.meshFirstTriangles[meshIndex] || local >= mesh.triangles.size()) {
        return std::nullopt;
    }
    const glm::mat4& objectFromWorld = bvh.objectFromWorld[instance];
    const glm::vec3 origin(objectFromWorld * glm::vec4(ray.origin, 1.0f));
    const glm::vec3 dir = glm::mat3(objectFromWorld) * ray.direction; // keeps t in metres
    const glm::uvec3 tri = mesh.triangles[local];
    const glm::vec3 p0 = mesh.positions[tri.x];
    const glm::vec3 e1 = mesh.positions[tri.y] - p0;
    const glm::vec3 e2 = mesh.positions[tri.z] - p0;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (det == 0.0f) return std::nullopt;
    const glm::vec3 s = origin - p0;
    const glm::vec3 q = glm::cross(s, e1);
    const float u = glm::dot(s, p) / det;
    const float v = glm::dot(dir, q) / det;
    if (u < -kBarycentricSlack || v < -kBarycentricSlack || u + v > 1.0f + kBarycentricSlack) {
        return std::nullopt;
    }
    return glm::dot(e2, q) / det;
}

class BvhGpuTest : public GlTest {};

// Default box city at the origin plus a second instance of its mesh that is translated, rotated
// and non-uniformly scaled: the top level has two overlapping boxes to sort out, and the bottom
// level sees rays whose object-space direction is not unit length.
Scene makeTwoCityScene() {
    Scene scene;
    addBoxCity(scene, BoxCityParams{}, glm::mat4(1.0f));
    glm::mat4 worldFromObject = glm::translate(glm::mat4(1.0f), glm::vec3(150.0f, 40.0f, 60.0f));
    worldFromObject = glm::rotate(worldFromObject, glm::radians(35.0f),
                                  glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    worldFromObject = glm::scale(worldFromObject, glm::vec3(0.5f, 1.5f, 0.8f));
    scene.instances.push_back({scene.instances[0].meshIndex, worldFromObject});
    return scene;
}

TEST_F(BvhGpuTest, TraceRaysBindingsMatchTheShader) {
    const gl::Program program = buildTraceRaysProgram();
    for (const auto& [block, binding] : {std::pair{"DebugRays", gpu::kBindingDebugRays},
                                         std::pair{"DebugResults", gpu::kBindingDebugResults}}) {
        const GLuint index =
            glGetProgramResourceIndex(program.getId(), GL_SHADER_STORAGE_BLOCK, block);
        ASSERT_NE(index, GL_INVALID_INDEX) << block;
        const GLenum property = GL_BUFFER_BINDING;
        GLint value = -1;
        glGetProgramResourceiv(program.getId(), GL_SHADER_STORAGE_BLOCK, index, 1, &property, 1,
                               nullptr, &value);
        EXPECT_EQ(value, static_cast<GLint>(binding)) << block;
    }
}

TEST_F(BvhGpuTest, MatchesCpuOnBoxCity) {
    constexpr int kRayCount = 10000;
    constexpr uint32_t kSeed = 20240611;
    constexpr float kBoundsGrowth = 0.2f; // origins also outside the city, looking in or away
    // Both sides run the same float Moller-Trumbore on object-space rays from the same
    // objectFromWorld (glm::inverse), but GLSL may fuse multiply-adds and its division is only
    // accurate to 2.5 ulp: the ray's transform and the ~10 operations behind t each differ by
    // a few ulp of the coordinates they work on, the origin's as much as t's (a ray from 190 m
    // out that hits 0.37 m away differed by 4e-5 m on an NVIDIA H200: 1e-4 of t, 2e-7 of the
    // origin's distance). So the tolerance is relative to t + |origin|: 1e-5 leaves a wide
    // margin over the few 1e-7 of those operations, yet stays far below the gap between
    // distinct surfaces of a city measured in metres.
    constexpr float kRelativeTolerance = 1e-5f;
    // Hits on enough rays and on both instances, so agreement is not agreement on misses.
    constexpr int kMinHitsPerInstance = 500;
    constexpr int kMaxReportedMismatches = 5;
    // A tie needs a ray to meet an edge or a coplanar face to within rounding, which random
    // rays rarely do: more than this points at a systematic fault, not at ties.
    constexpr int kMaxTieMismatches = kRayCount / 100;

    const Scene scene = makeTwoCityScene();
    const GpuScene gpuScene(scene, kLightResolution);
    const BvhScene bvh = buildSceneBvh(scene);

    const Aabb bounds = scene.computeWorldBounds();
    const glm::vec3 lo = bounds.lo - 0.5f * kBoundsGrowth * bounds.getExtent();
    const glm::vec3 size = (1.0f + kBoundsGrowth) * bounds.getExtent();
    std::mt19937 rng(kSeed);
    std::vector<Ray> rays(kRayCount);
    for (Ray& ray : rays) {
        ray.origin = lo + size * glm::vec3(drawUniform(rng), drawUniform(rng), drawUniform(rng));
        ray.direction = drawDirection(rng);
        ray.tMax = kLongRayM;
    }

    const std::vector<GpuHit> gpuHits = traceOnGpu(gpuScene, rays);
    int hardMismatches = 0;
    int tieMismatches = 0;
    int hitsPerInstance[2] = {0, 0};
    for (size_t i = 0; i < rays.size(); ++i) {
        const std::optional<Hit> cpu = intersect(bvh, scene, rays[i]);
        const GpuHit& gpu = gpuHits[i];
        if (cpu) ++hitsPerInstance[cpu->instanceIndex];
        bool agrees = cpu.has_value() == gpu.found;
        bool isTie = false;
        if (agrees && cpu) {
            const float tolerance = kRelativeTolerance * (cpu->t + glm::length(rays[i].origin));
            const bool closeT = std::abs(gpu.t - cpu->t) <= tolerance;
            const bool sameTriangle =
                gpu.triangle == cpu->triangleIndex && gpu.instance == cpu->instanceIndex;
            // Another triangle at the same distance: the ray crosses a shared edge or meets
            // coplanar faces, and which of them wins is down to rounding. The GPU's triangle
            // must really lie there, or a wrong index at the right distance would pass.
            if (!sameTriangle && closeT) {
                const std::optional<float> tClaimed =
                    intersectClaimedTriangle(bvh, scene, rays[i], gpu.instance, gpu.triangle);
                isTie = tClaimed && std::abs(*tClaimed - cpu->t) <= tolerance;
            }
            agrees = sameTriangle && closeT;
        }
        if (agrees) continue;
        if (isTie) {
            ++tieMismatches;
            continue;
        }
        if (++hardMismatches <= kMaxReportedMismatches) {
            ADD_FAILURE() << strCat("ray ", i, " origin (", rays[i].origin.x, ", ",
                                    rays[i].origin.y, ", ", rays[i].origin.z, ") direction (",
                                    rays[i].direction.x, ", ", rays[i].direction.y, ", ",
                                    rays[i].direction.z, "): cpu ",
                                    cpu ? strCat("hit triangle ", cpu->triangleIndex, " instance ",
                                                 cpu->instanceIndex, " t ", cpu->t)
                                        : std::string("miss"),
                                    ", gpu ",
                                    gpu.found ? strCat("hit triangle ", gpu.triangle, " instance ",
                                                       gpu.instance, " t ", gpu.t)
                                              : std::string("miss"));
        }
    }
    EXPECT_EQ(hardMismatches, 0);
    std::cout << strCat("[ BvhGpu   ] ", kRayCount, " rays: ", hitsPerInstance[0], " + ",
                        hitsPerInstance[1], " hits, ", tieMismatches,
                        " tie mismatches (another triangle at the same distance)\n");
    EXPECT_LE(tieMismatches, kMaxTieMismatches);
    EXPECT_GE(hitsPerInstance[0], kMinHitsPerInstance);
    EXPECT_GE(hitsPerInstance[1], kMinHitsPerInstance);
}

TEST_F(BvhGpuTest, ReportsNoHitForRaysThatMissEverything) {
    // One 2 m square facing +z at z = -10: a scene with almost nothing in it.
    constexpr float kQuadZ = -10.0f;
    constexpr float kShortRayM = 5.0f; // stops halfway to the square
    const glm::mat4 atQuadZ = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, kQuadZ));
    const Scene scene = makeGreySquares({&atQuadZ, 1});

    const glm::vec3 towardQuad(0.0f, 0.0f, -1.0f);
    const glm::vec3 alongQuad = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    const std::vector<Ray> misses = {
        {glm::vec3(0.0f), -towardQuad, kLongRayM},                     // facing away
        {glm::vec3(3.0f, 0.0f, 0.0f), towardQuad, kLongRayM},          // passes beside it
        {glm::vec3(0.0f), alongQuad, kLongRayM},                       // parallel to its plane
        {glm::vec3(0.0f, 0.0f, kQuadZ - 1.0f), towardQuad, kLongRayM}, // starts behind it
        {glm::vec3(0.0f), towardQuad, kShortRayM},                     // ends before it
    };
    // The control: the same scene and program do report the square when a ray reaches it.
    const Ray control{glm::vec3(0.25f, 0.5f, 0.0f), towardQuad, kLongRayM};
    std::vector<Ray> rays = misses;
    rays.push_back(control);

    const GpuScene gpuScene(scene, kLightResolution);
    const BvhScene bvh = buildSceneBvh(scene);
    const std::vector<GpuHit> hits = traceOnGpu(gpuScene, rays);
    for (size_t i = 0; i < misses.size(); ++i) {
        EXPECT_FALSE(hits[i].found) << "ray " << i;
        EXPECT_EQ(hits[i].t, misses[i].tMax) << "ray " << i << ": a miss reports tMax";
        EXPECT_FALSE(intersect(bvh, scene, misses[i]).has_value()) << "ray " << i;
    }
    ASSERT_TRUE(hits.back().found);
    EXPECT_FLOAT_EQ(hits.back().t, -kQuadZ);
    EXPECT_EQ(hits.back().instance, 0u);
}

} // namespace
} // namespace ispm::test
