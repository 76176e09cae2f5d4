// Textures through the whole pipeline, on a glTF file the test writes (support/gltf_scenes): a
// floor with a red and white checker under a spot light. Direct light shows the checker square by
// square; light bounced off the floor onto a white ceiling takes the checker's mean colour, once
// through the light's G-buffer (first bounce) and once through the photon tracer (second
// bounce), and the reference path tracer agrees. An untextured floor would give a grey ceiling.
// A mirror shows the checker too: the specular pass reads the texture where its rays hit.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"
#include "support/gltf_scenes.h"
#include "support/render_support.h"

#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <shared/surface_brdf.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ispm::test {
namespace {

class GltfTextureTest : public GlTest {};

constexpr double kSpotWattsPerSr = 1.0; // CheckerRoom's 683 cd

Scene loadRoom(const CheckerRoom& room, const std::string& name) {
    const std::string path = (std::filesystem::path(::testing::TempDir()) / name).string();
    writeCheckerRoomGltf(path, room);
    Scene scene = loadScene(path);
    std::filesystem::remove(path);
    return scene;
}

Settings makeSettings(int size, int bounces) {
    Settings settings = makeTestSettings(
        {{"width", size}, {"height", size}, {"bounces", bounces}, {"photons", 20000}});
    return settings;
}

// The same scene with every material untextured: what the bounds below must fail.
void removeTextures(Scene& scene) {
    for (Material& m : scene.materials)
        m.diffuseTexture = kNoTexture;
}

// Mean red over mean green of the image: the colour of light bounced off the red and white
// checker. Its floor reflects about 0.96 x colour + 0.04 per channel (glTF's dielectric,
// gltf_units.h), red (1.00, 0.04, 0.04) and white (1, 1, 1) in equal parts, so the ceiling's light
// has red/green near 1.00 / 0.52 = 1.92; a floor read without its texture reflects white and
// gives 1.
double computeRedOverGreen(const Image& image) {
    glm::dvec3 sum(0.0);
    for (const glm::vec3& p : image.pixels)
        sum += glm::dvec3(p);
    EXPECT_GT(sum.g, 0.0) << "a black image shows no colour";
    return sum.r / sum.g;
}

// The bound on red/green: the checker's 1.92, give or take how unevenly the ceiling's points see
// the squares (each sees the whole floor, squares of both colours placed symmetrically) and the
// noise of 20,000 photons or 64 samples. Measured (seed 1): ispm 1.94 (one bounce) and 1.98
// (second bounce), reference 1.93 and 1.95; untextured 1.00, and 1.00 too with the texture
// lookup taken out of photon_trace.comp or reference.comp (each such test then fails).
constexpr double kMinRedOverGreen = 1.6;
constexpr double kMaxRedOverGreen = 2.3;

TEST_F(GltfTextureTest, DirectLightShowsTheChecker) {
    CheckerRoom room;
    room.ceilingM = 0.0f; // the camera above looks down at the floor
    room.cameraPositionM = {0.0f, 2.5f, 0.0f};
    room.cameraYFovRad = 2.0f * std::atan(1.0f / 2.5f); // the floor fills the image
    const Scene scene = loadRoom(room, "gltf_direct_room.gltf");
    constexpr int kSize = 64;
    const Image image = renderAov(scene, makeSettings(kSize, 0), Aov::Direct);

    const float square = 2.0f * room.halfM / float(room.checks);
    constexpr float kEdgeMarginM = 0.05f; // texture filtering blends colours at square edges
    int red = 0;
    int white = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 p = projectToGround(scene, kSize, kSize, x + 0.5, y + 0.5);
            const float u = (float(p.x) + room.halfM) / square;
            const float v = (float(p.z) + room.halfM) / square;
            const float du = u - std::floor(u);
            const float dv = v - std::floor(v);
            if (std::min({du, dv, 1.0f - du, 1.0f - dv}) * square < kEdgeMarginM) continue;
            if (u < 0.0f || v < 0.0f || u >= float(room.checks) || v >= float(room.checks)) {
                continue;
            }
            const glm::vec3 albedo = getCheckerColor(room, int(u), int(v));
            // Lambert at 0.96 x albedo plus the 0.04 white coat, a Phong lobe of exponent 1
            // (roughness 1), split by Schlick's Fresnel as the shared reflection model does
            // (shared/surface_brdf.h, integrated by tests/unit/surface_brdf_test.cpp); under
            // E = I cos / d^2 from the spot at (0, 1, 0).
            const glm::dvec3 toLight = glm::normalize(glm::dvec3(0.0, 1.0, 0.0) - p);
            const glm::dvec3 toEye = glm::normalize(glm::dvec3(room.cameraPositionM) - p);
            const double d2 = p.x * p.x + 1.0 + p.z * p.z;
            const double irradiance = kSpotWattsPerSr * toLight.y / d2;
            const glm::vec3 brdf = gpu::evaluateSurfaceBrdf(
                0.96f * albedo, glm::vec4(glm::vec3(0.04f), 1.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                glm::vec3(toLight), glm::vec3(toEye));
            const glm::dvec3 expected = glm::dvec3(brdf) * irradiance;
            const glm::vec3 actual = image.at(x, y);
            // 2%: 8-bit sRGB texels of 0 and 255 decode exactly; the G-buffer's 16-bit normals and
            // the spot's smoothstep (inside its inner cone here) leave well under 1%.
            constexpr double kTolerance = 0.02;
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(actual[c], expected[c], kTolerance * expected.r + 1e-6)
                    << "pixel " << x << "," << y << " channel " << c;
            }
            (albedo.g > 0.5f ? white : red)++;
        }
    }
    // Both colours seen over many pixels each (a 64 x 64 view of 16 squares).
    EXPECT_GT(red, 800);
    EXPECT_GT(white, 800);
}

// Light from a spot pointing down at the floor reaches the ceiling after one bounce: the
// photons' first bounce reads the light G-buffer's textured diffuse.
TEST_F(GltfTextureTest, FirstBounceCarriesTheCheckerColours) {
    CheckerRoom room;
    room.cameraPositionM = {0.0f, 0.5f, 0.0f};
    room.cameraUp = true;
    Scene scene = loadRoom(room, "gltf_bounce_room.gltf");
    constexpr int kSize = 32;
    const Settings settings = makeSettings(kSize, 1);
    const double ispm = computeRedOverGreen(renderAov(scene, settings, Aov::Indirect));
    constexpr int kSpp = 64;
    const double reference = computeRedOverGreen(renderReferenceIndirect(scene, settings, kSpp));
    // The same floor without its texture: the bound must fail it.
    removeTextures(scene);
    const double untextured = computeRedOverGreen(renderAov(scene, settings, Aov::Indirect));
    std::printf("ceiling red/green, one bounce: ispm %.3f, reference %.3f, untextured %.3f\n", ispm,
                reference, untextured);
    EXPECT_GT(ispm, kMinRedOverGreen);
    EXPECT_LT(ispm, kMaxRedOverGreen);
    EXPECT_GT(reference, kMinRedOverGreen);
    EXPECT_LT(reference, kMaxRedOverGreen);
    EXPECT_LT(untextured, kMinRedOverGreen);
}

// A spot pointing up lights the ceiling; its light reaches the ceiling again only by way of the
// floor (ceiling -> floor -> ceiling), so the colour comes from the compute tracer's texture
// lookup at the floor.
TEST_F(GltfTextureTest, TracedBounceCarriesTheCheckerColours) {
    CheckerRoom room;
    room.lightUp = true;
    room.cameraPositionM = {0.0f, 0.5f, 0.0f};
    room.cameraUp = true;
    const Scene scene = loadRoom(room, "gltf_trace_room.gltf");
    constexpr int kSize = 32;
    const Settings settings = makeSettings(kSize, 2);
    const double ispm = computeRedOverGreen(renderAov(scene, settings, Aov::Indirect));
    constexpr int kSpp = 64;
    const double reference = computeRedOverGreen(renderReferenceIndirect(scene, settings, kSpp));
    std::printf("ceiling red/green, second bounce: ispm %.3f, reference %.3f\n", ispm, reference);
    EXPECT_GT(ispm, kMinRedOverGreen);
    EXPECT_LT(ispm, kMaxRedOverGreen);
    EXPECT_GT(reference, kMinRedOverGreen);
    EXPECT_LT(reference, kMaxRedOverGreen);
}

// The ceiling made a mirror: the camera looking up sees the lit floor in it, through the
// specular pass's rays, whose hits read the floor's texture as the reference's do. Measured
// (seed 1): red/green 1.923 in the mirror (the checker's 1.92), 1.000 untextured, and 1.000 with
// the texture lookup taken out of specular_trace.comp (the test then fails).
TEST_F(GltfTextureTest, MirrorShowsTheChecker) {
    CheckerRoom room;
    room.cameraPositionM = {0.0f, 0.5f, 0.0f};
    room.cameraUp = true;
    Scene scene = loadRoom(room, "gltf_mirror_room.gltf");
    constexpr float kMirrorRho = 0.9f;
    constexpr float kMirrorExponent = 10000.0f; // a mirror lobe (the specular pass traces it)
    int mirrors = 0;
    for (Material& m : scene.materials) {
        if (m.diffuseTexture != kNoTexture) continue; // the floor keeps its checker
        m.diffuse = glm::vec3(0.0f);
        m.specular = glm::vec3(kMirrorRho);
        m.phongExponent = kMirrorExponent;
        ++mirrors;
    }
    ASSERT_GT(mirrors, 0) << "the room has no untextured ceiling to make a mirror of";
    constexpr int kSize = 32;
    // One bounce: the specular pass traces `bounces` levels at most; few photons, since the
    // mirror shows the floor's direct light and the floor's bounced light is small beside it.
    const Settings settings = withSettings(makeSettings(kSize, 1), {{"photons", 2000}});
    const double ispm = computeRedOverGreen(renderAov(scene, settings, Aov::Total));
    removeTextures(scene);
    const double untextured = computeRedOverGreen(renderAov(scene, settings, Aov::Total));
    std::printf("mirror red/green: ispm %.3f, untextured %.3f\n", ispm, untextured);
    EXPECT_GT(ispm, kMinRedOverGreen);
    EXPECT_LT(ispm, kMaxRedOverGreen);
    EXPECT_LT(untextured, kMinRedOverGreen);
}

} // namespace
} // namespace ispm::test
