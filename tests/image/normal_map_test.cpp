// Normal maps against closed forms: a plane whose normal map tilts every point's normal by 30
// degrees toward a known direction of its tangent frame, lit by the sun, shades as a Lambertian
// surface with the tilted normal, rho / pi x E x cos(tilted normal, light), in ispm's direct
// light and in the path tracer. The texture coordinates' layout (flipped v, u turned by 90
// degrees) turns the tilt with them, with tangents from the file or generated.
#include "support/gl_fixture.h"
#include "support/gltf_scenes.h"
#include "support/render_support.h"
#include "support/test_settings.h"

#include "scene/scene_loader.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ispm::test {
namespace {

constexpr float kAlbedo = 0.5f;
constexpr float kIrradiance = 2.0f; // W/m^2 facing the sun
// Toward the sun: chosen so that the tilted normal's cosine differs by more than 5% between
// every direction the tilt could take (+-x, +-z) and no tilt at all (0.82, 0.40, 0.33, 0.90,
// 0.71), so a frame turned or mirrored the wrong way fails.
const glm::vec3 kToSun = glm::normalize(glm::vec3(0.6f, 1.0f, -0.8f));
constexpr float kTiltRad = glm::pi<float>() / 6.0f; // 30 degrees
constexpr int kSize = 32;
// Sample positions do not matter on a plane under the sun (no shadow, no falloff): a few
// samples per pixel make the path tracer's image exact to float rounding.
constexpr int kSpp = 2;

class NormalMapTest : public GlTest {};

// The texel that tilts the normal by kTiltRad toward the tangent (alongBitangent false) or the
// bitangent, as bytes (2 rgb / 255 - 1 is the tangent-space normal).
std::array<uint8_t, 3> makeTiltTexel(bool alongBitangent) {
    const glm::vec3 n(alongBitangent ? 0.0f : std::sin(kTiltRad),
                      alongBitangent ? std::sin(kTiltRad) : 0.0f, std::cos(kTiltRad));
    std::array<uint8_t, 3> texel{};
    for (int c = 0; c < 3; ++c)
        texel[size_t(c)] = uint8_t(std::lround((n[c] + 1.0f) * 0.5f * 255.0f));
    return texel;
}

// The world-space normal the texel gives on the plane (normal +y), with the tangent and
// bitangent of the layout worked out by hand (support/gltf_scenes.h), from the bytes as the GPU
// reads them.
glm::vec3 computeExpectedNormal(const std::array<uint8_t, 3>& texel, PlaneUv uv) {
    glm::vec3 t(0.0f);
    glm::vec3 b(0.0f);
    switch (uv) {
    case PlaneUv::Standard:
        t = {1, 0, 0};
        b = {0, 0, -1};
        break;
    case PlaneUv::FlippedV:
        t = {1, 0, 0};
        b = {0, 0, 1};
        break;
    case PlaneUv::Rotated:
        t = {0, 0, 1};
        b = {1, 0, 0};
        break;
    }
    glm::vec3 m;
    for (int c = 0; c < 3; ++c)
        m[c] = 2.0f * float(texel[size_t(c)]) / 255.0f - 1.0f;
    return glm::normalize(m.x * t + m.y * b + m.z * glm::vec3(0, 1, 0));
}

Scene makePlaneScene(const NormalMappedPlane& plane, const std::string& name) {
    const std::string path = (std::filesystem::path(::testing::TempDir()) / name).string();
    writeNormalMappedPlaneGltf(path, plane);
    Scene scene = loadScene(path);
    std::filesystem::remove(path);
    for (Material& m : scene.materials) { // Lambertian: the closed form below
        m.diffuse = glm::vec3(kAlbedo);
        m.specular = glm::vec3(0.0f);
    }
    Light sun;
    sun.type = LightType::Sun;
    sun.direction = -kToSun;
    sun.irradiance = glm::vec3(kIrradiance);
    scene.lights.push_back(sun);
    // Looking straight down from 2 m: a 40-degree view sees the plane alone (+-0.73 m).
    scene.camera.position = {0.0f, 2.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.fovYDeg = 40.0f;
    return scene;
}

// The largest relative difference of any pixel and channel from `expected`.
double measureWorstError(const Image& image, double expected) {
    double worst = 0.0;
    for (const glm::vec3& p : image.pixels) {
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(p[c]) - expected) / expected);
    }
    return worst;
}

struct Case {
    const char* name;
    PlaneUv uv;
    bool fileTangents;
    bool alongBitangent;
    bool normals; // NORMAL in the file; else flat-shaded (the face's normal)
};

// Measured: worst pixel 0.04% off in ispm's direct light (the G-buffer's 16-bit normal), 0.00%
// in the path tracer, in every case. The 2% bound is the issue's; the other directions the tilt
// could take are 5% or more away (kToSun), as is no tilt at all: with the handedness left out
// of the frame the flipped-v cases miss by 169% in both renderers.
TEST_F(NormalMapTest, ConstantTiltShadesAsTheTiltedNormal) {
    const Case cases[] = {
        {"u along +x, generated tangents, tilt toward the tangent", PlaneUv::Standard, false, false,
         true},
        {"u along +x, the file's tangents", PlaneUv::Standard, true, false, true},
        {"u along +x, no NORMAL (flat)", PlaneUv::Standard, false, false, false},
        {"u along +x, tilt toward the bitangent (-z)", PlaneUv::Standard, false, true, true},
        {"v flipped, generated tangents (handedness -1): bitangent +z", PlaneUv::FlippedV, false,
         true, true},
        {"v flipped, the file's tangents", PlaneUv::FlippedV, true, true, true},
        {"u along +z, tilt toward the tangent", PlaneUv::Rotated, false, false, true},
    };
    const Settings settings =
        makeTestSettings({{"width", kSize}, {"height", kSize}, {"bounces", 0}});
    constexpr double kTolerance = 0.02;
    const double flat =
        double(kAlbedo) / glm::pi<double>() * double(kIrradiance) * double(kToSun.y);
    for (const Case& c : cases) {
        NormalMappedPlane plane;
        plane.uv = c.uv;
        plane.writeTangents = c.fileTangents;
        plane.writeNormals = c.normals;
        plane.texel = makeTiltTexel(c.alongBitangent);
        const Scene scene = makePlaneScene(plane, "normal_mapped_plane.gltf");
        const glm::vec3 n = computeExpectedNormal(plane.texel, c.uv);
        const double cosine = double(glm::dot(n, kToSun));
        const double expected = double(kAlbedo) / glm::pi<double>() * double(kIrradiance) * cosine;
        ASSERT_GT(expected, 0.0);
        // The tilt changes the light by more than the bound: an unread map fails.
        ASSERT_GT(std::abs(expected / flat - 1.0), 2.0 * kTolerance) << c.name;
        const double ispm = measureWorstError(renderAov(scene, settings, Aov::Direct), expected);
        const double traced =
            measureWorstError(renderReference(scene, "path", kSize, kSpp, 0), expected);
        std::printf("%s: expected %.4f (cos %.3f; untilted %.4f), worst error ispm %.4f, path "
                    "tracer %.4f\n",
                    c.name, expected, cosine, flat, ispm, traced);
        EXPECT_LT(ispm, kTolerance) << c.name;
        EXPECT_LT(traced, kTolerance) << c.name;
    }
}

// A white wall (x = -1, facing +x) lit by the sun beside the normal-mapped plane, whose normals
// lean 30 degrees away from it: the light the wall sends down reaches the plane as photons,
// stored where the photon tracer's rays hit it. Their splats are discs flattened about the
// normal each photon keeps, which must be the plane's own, not the map's, or each disc cuts the
// plane in a strip; and each pixel takes the photon's flux by its turned normal, |wi.ns| /
// |wi.n|, nothing from below that normal's horizon, as the path tracer's BRDF does. ispm's
// indirect light on the plane against the path tracer's (bounces 1 minus 0), over the image's
// middle. Measured: 1.004; 0.185 with the photons keeping the mapped normal, 3.65 without the
// splats' factor (the same plane with a flat map: 1.024).
TEST_F(NormalMapTest, PhotonsOnTheMappedPlaneSplatInItsPlane) {
    NormalMappedPlane plane;
    plane.texel = makeTiltTexel(false);
    Scene scene = makePlaneScene(plane, "normal_mapped_floor.gltf");
    scene.lights[0].direction = glm::normalize(glm::vec3(-1.0f, -0.6f, 0.0f));
    Material white;
    white.name = "wall";
    white.diffuse = glm::vec3(0.8f);
    scene.materials.push_back(white);
    Mesh wall;
    wall.name = "wall";
    wall.positions = {{-1, 0, -1}, {-1, 0, 1}, {-1, 2, 1}, {-1, 2, -1}};
    wall.triangles = {{0, 1, 2}, {0, 2, 3}}; // facing +x
    wall.triangleMaterials.assign(2, static_cast<uint32_t>(scene.materials.size() - 1));
    scene.meshes.push_back(wall);
    scene.instances.push_back({static_cast<uint32_t>(scene.meshes.size() - 1), glm::mat4(1.0f)});
    constexpr int kIndirectSize = 48;
    constexpr int kIndirectSpp = 64;
    const Settings settings =
        makeTestSettings({{"width", kIndirectSize}, {"height", kIndirectSize}, {"bounces", 1}});
    const Image ispm = renderAov(scene, settings, Aov::Indirect);
    const Image reference = renderReferenceIndirect(scene, settings, kIndirectSpp);
    // The middle half of the image: the plane alone, away from the wall's foot.
    double ispmSum = 0.0;
    double referenceSum = 0.0;
    for (int y = kIndirectSize / 4; y < 3 * kIndirectSize / 4; ++y) {
        for (int x = kIndirectSize / 4; x < 3 * kIndirectSize / 4; ++x) {
            ispmSum += double(ispm.at(x, y).g);
            referenceSum += double(reference.at(x, y).g);
        }
    }
    std::printf("indirect light on the plane: ispm %.5f, path tracer %.5f (%.3f)\n", ispmSum,
                referenceSum, ispmSum / referenceSum);
    ASSERT_GT(referenceSum, 0.0) << "no light reaches the plane from the wall";
    // 10%: the photons' density estimate against 64 paths a pixel, well inside the failures
    // measured above.
    constexpr double kTolerance = 0.1;
    EXPECT_NEAR(ispmSum / referenceSum, 1.0, kTolerance);
}

} // namespace
} // namespace ispm::test
