// Emitting triangles as lights against closed forms (docs/design.md "Emitters"): the radiance of
// a diffuse floor under an emitting plane and under a small emitting square, in ispm's direct
// light and in the path tracer; one-sided emission; the emitters' photons against the path
// tracer's indirect light.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"
#include "support/render_support.h"
#include "support/test_settings.h"

#include "image/metrics.h"
#include "scene/emitters.h"
#include "scene/scene_loader.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace ispm::test {
namespace {

constexpr double kRho = 0.5;
constexpr double kRadiance = 2.0; // W/(m^2 sr)
constexpr double kHeightM = 1.0;  // the emitter above the floor
constexpr int kSize = 32;

// The form factor from a point to the rectangle between its foot (0, 0) and (a, b) in a parallel
// plane h above it (the corner case of the catalogued differential-area-to-rectangle factor),
// signed by the quadrant so that rectangles add and subtract.
double computeCornerFactor(double a, double b, double h) {
    const double x = std::abs(a) / h;
    const double y = std::abs(b) / h;
    const double sx = std::sqrt(1.0 + x * x);
    const double sy = std::sqrt(1.0 + y * y);
    const double f =
        (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / glm::two_pi<double>();
    return (a < 0.0) != (b < 0.0) ? -f : f;
}

// The form factor from floor point (x, z) to the square of half-side s centred above the origin.
double computeSquareFactor(double x, double z, double s, double h) {
    return computeCornerFactor(s - x, s - z, h) - computeCornerFactor(-s - x, s - z, h) -
           computeCornerFactor(s - x, -s - z, h) + computeCornerFactor(-s - x, -s - z, h);
}

// A grey floor (makeLitPlane's, without its light) under an emitting square of half-side `halfM`
// at kHeightM, emitting downward (its winding faces -y), black; the camera between them looking
// down at the floor around the square's axis.
Scene makeEmitterOverFloor(float halfM) {
    Scene scene = makeLitPlane(float(kRho), 0.0f, float(kHeightM), 1000.0f);
    scene.lights.clear();
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = glm::vec3(float(kRadiance));
    scene.materials.push_back(lamp);
    Mesh square;
    square.name = "lamp";
    const float s = halfM;
    const auto h = float(kHeightM);
    square.positions = {{-s, h, -s}, {s, h, -s}, {s, h, s}, {-s, h, s}}; // winding normal -y
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    square.triangleMaterials = {1, 1};
    scene.meshes.push_back(square);
    scene.instances.push_back({1, glm::mat4(1.0f)});
    scene.camera.position = {0.0f, 0.5f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.fovYDeg = 40.0f;
    return scene;
}

// The floor's radiance rho / pi x E, E = pi L x the form factor, over the image's pixels, and the
// mean of `image` and of it over them all.
struct Means {
    double actual = 0.0;
    double expected = 0.0;
};
Means compareWithClosedForm(const Scene& scene, const Image& image, float halfM) {
    Means m;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 p = projectToGround(scene, kSize, kSize, x + 0.5, y + 0.5);
            m.expected += kRho * kRadiance * computeSquareFactor(p.x, p.z, halfM, kHeightM);
            m.actual += double(image.at(x, y).g);
        }
    }
    m.actual /= kSize * kSize;
    m.expected /= kSize * kSize;
    return m;
}

class EmitterTest : public GlTest {};

// ispm's direct light and the path tracer's, each within 1% of the closed form over the image
// (the bar; the sampling noise of 8 stratified samples per pixel averages out over the
// 1,024 pixels far below it). Returns ispm's image.
Image expectDirectLightMatchesClosedForm(const Scene& scene, float halfM) {
    const Image direct =
        renderAov(scene, makeTestSettings({{"width", kSize}, {"height", kSize}, {"bounces", 0}}),
                  Aov::Direct);
    const Means ispm = compareWithClosedForm(scene, direct, halfM);
    EXPECT_NEAR(ispm.actual, ispm.expected, 0.01 * ispm.expected) << "ispm";
    const Image reference = renderReference(scene, "path", kSize, 16, 0);
    const Means path = compareWithClosedForm(scene, reference, halfM);
    EXPECT_NEAR(path.actual, path.expected, 0.01 * path.expected) << "path tracer";
    return direct;
}

TEST_F(EmitterTest, PlaneEmitterLightsTheFloorWithPiL) {
    // A 200 m emitter 1 m above: E = pi L within 1e-4, so the floor shows rho L. Sampled by
    // area alone it would take thousands of samples (the light comes from the few square metres
    // overhead); by solid angle it takes a few.
    constexpr float kHalf = 100.0f;
    const Scene scene = makeEmitterOverFloor(kHalf);
    EXPECT_NEAR(compareWithClosedForm(scene, Image(kSize, kSize), kHalf).expected, kRho * kRadiance,
                1e-3 * kRho * kRadiance);
    expectDirectLightMatchesClosedForm(scene, kHalf);
}

TEST_F(EmitterTest, SmallSquareMatchesTheFormFactor) {
    // A 20 cm square 1 m above: the irradiance falls off over the image (form factor 0.0127 on
    // the axis).
    constexpr float kHalf = 0.1f;
    const Scene scene = makeEmitterOverFloor(kHalf);
    const Image direct = expectDirectLightMatchesClosedForm(scene, kHalf);
    // Every pixel within 3%: the solid angle sampling leaves a pixel's noise in the cosines alone.
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 p = projectToGround(scene, kSize, kSize, x + 0.5, y + 0.5);
            const double expected =
                kRho * kRadiance * computeSquareFactor(p.x, p.z, kHalf, kHeightM);
            ASSERT_NEAR(double(direct.at(x, y).g), expected, 0.03 * expected)
                << "pixel " << x << "," << y;
        }
    }
}

TEST_F(EmitterTest, OneSidedEmitterLightsOnlyItsFront) {
    // The same square turned over (its winding faces up): the floor gets nothing, and the
    // camera sees its back black; two-sided, the floor is lit as before.
    constexpr float kHalf = 0.1f;
    Scene scene = makeEmitterOverFloor(kHalf);
    for (glm::uvec3& t : scene.meshes[1].triangles)
        std::swap(t.y, t.z);
    const Settings settings =
        makeTestSettings({{"width", kSize}, {"height", kSize}, {"bounces", 0}});
    const Image back = renderAov(scene, settings, Aov::Direct);
    double sum = 0.0;
    for (const glm::vec3& p : back.pixels)
        sum += double(p.r + p.g + p.b);
    EXPECT_EQ(sum, 0.0);
    scene.materials[1].emissionTwoSided = true;
    const Image both = renderAov(scene, settings, Aov::Direct);
    const Means m = compareWithClosedForm(scene, both, kHalf);
    EXPECT_NEAR(m.actual, m.expected, 0.01 * m.expected);
}

TEST_F(EmitterTest, UniformSkyLightsAnOpenPlaneWithRhoL) {
    // An unoccluded diffuse floor under a constant environment of radiance L reflects rho L:
    // ispm's direct light (cosine-weighted rays to the sky), its whole frame (the sky's photons
    // find nothing to bounce off but the floor, which they leave) and the path tracer.
    Scene scene = makeEmitterOverFloor(0.1f);
    scene.instances.pop_back(); // no emitter
    scene.environment.type = EnvironmentType::Constant;
    scene.environment.radiance = glm::vec3(float(kRadiance));
    const Settings settings = makeTestSettings({{"width", kSize}, {"height", kSize}});
    const double expected = kRho * kRadiance;
    for (const Aov aov : {Aov::Direct, Aov::Total}) {
        const Image image = renderAov(scene, settings, aov);
        double mean = 0.0;
        for (const glm::vec3& p : image.pixels)
            mean += double(p.g) / double(image.pixels.size());
        // 1%: the bar; a pixel's 8 cosine-weighted rays all reach the sky (no noise).
        EXPECT_NEAR(mean, expected, 0.01 * expected);
    }
    const Image reference = renderReference(scene, "path", kSize, 16, 3);
    double mean = 0.0;
    for (const glm::vec3& p : reference.pixels)
        mean += double(p.g) / double(reference.pixels.size());
    EXPECT_NEAR(mean, expected, 0.01 * expected);
}

TEST_F(EmitterTest, EmittersPowerIsPiLTimesAreaTimesSides) {
    Scene scene = makeEmitterOverFloor(0.5f);
    Emitters emitters = collectEmitters(scene);
    ASSERT_EQ(emitters.groups.size(), 1u);
    EXPECT_EQ(emitters.groups[0].count, 2u);
    const double area = 1.0; // 1 m square
    EXPECT_NEAR(emitters.groups[0].powerW.y, glm::pi<double>() * kRadiance * area, 1e-4);
    scene.materials[1].emissionTwoSided = true;
    emitters = collectEmitters(scene);
    EXPECT_NEAR(emitters.groups[0].powerW.y, 2.0 * glm::pi<double>() * kRadiance * area, 1e-4);
    // A triangle of no area emits nothing and is named in the warning.
    scene.meshes[1].positions[2] = scene.meshes[1].positions[1];
    emitters = collectEmitters(scene);
    EXPECT_EQ(emitters.groups[0].count, 1u);
    EXPECT_NE(describeDroppedEmitters(scene).find("mesh 'lamp'"), std::string::npos);
}

TEST_F(EmitterTest, CornellAreaIndirectLightMatchesThePathTracer) {
    // The Cornell box lit by its ceiling lamp alone: every photon comes from the emitter. Its
    // indirect light against the path tracer's at 64x64: energy within 5% and rel RMSE (4x4)
    // under 0.3 (256 paths a pixel leave the reference's own noise at about 0.1 of the mean;
    // the one frame's splat noise and bias measured 0.986 and 0.18 at 128x128).
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell_area.json");
    const Settings settings = makeTestSettings({{"width", 64}, {"height", 64}, {"bounces", 3}});
    const Image indirect = renderAov(scene, settings, Aov::Indirect);
    const Image reference = renderReferenceIndirect(scene, settings, 256);
    EXPECT_NEAR(computeEnergyRatio(indirect, reference), 1.0, 0.05);
    EXPECT_LT(computeRelRmse(indirect, reference, 4), 0.3);
}

TEST_F(EmitterTest, LightTracerAgreesWithThePathTracerOnTheLamp) {
    // Two independent estimators of the same image: light paths leaving points of the lamp
    // (the camera sees the lamp through light_resolve.comp's ray) against camera paths with MIS.
    // 3% on the image's energy: both carry about 1% noise at these counts, and a lamp counted
    // twice or a side missed is 2x or 0.5x.
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell_area.json");
    const Image light = renderReference(scene, "light", 48, 64, 3);
    const Image path = renderReference(scene, "path", 48, 256, 3);
    EXPECT_NEAR(computeEnergyRatio(light, path), 1.0, 0.03);
}

} // namespace
} // namespace ispm::test
