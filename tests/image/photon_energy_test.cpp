// Energy of the photon pipeline, against closed forms: photons inside a closed diffuse box, and
// one splat on a plane.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "render/photon_density_pass.h"
#include "render/readback.h"
#include "render/splat_pass.h"
#include "support/test_settings.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace ispm::test {
namespace {

class PhotonEnergyTest : public GlTest {};

// A closed box [-1,1]^3 (two-sided walls) of grey diffuse albedo rho, a point light inside.
Scene makeClosedBox(float rho, const glm::vec3& lightPosition, float intensity) {
    Scene scene;
    scene.sourcePath = "closed box";
    Material m;
    m.name = "walls";
    m.diffuse = glm::vec3(rho);
    scene.materials.push_back(m);
    Mesh mesh;
    mesh.name = "box";
    for (int i = 0; i < 8; ++i) {
        mesh.positions.emplace_back((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f,
                                    (i & 4) ? 1.0f : -1.0f);
    }
    const glm::uvec4 faces[6] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const glm::uvec4& f : faces) {
        mesh.triangles.emplace_back(f.x, f.y, f.z);
        mesh.triangles.emplace_back(f.x, f.z, f.w);
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {0u, 0u});
    }
    scene.meshes.push_back(mesh);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    Light light;
    light.type = LightType::Point;
    light.position = lightPosition;
    light.intensity = glm::vec3(intensity);
    scene.lights.push_back(light);
    scene.camera.position = {0.0f, 0.0f, 0.9f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    return scene;
}

TEST_F(PhotonEnergyTest, StoredPowerIsLightPowerTimesGeometricSeries) {
    constexpr float kRho = 0.6f;
    constexpr float kIntensity = 2.0f; // W/sr
    constexpr int kPhotons = 50000;
    // Off-centre so the walls are hit at every angle, not only head-on.
    const Scene scene = makeClosedBox(kRho, {0.3f, -0.2f, 0.1f}, kIntensity);
    const double lightPower = 4.0 * glm::pi<double>() * double(kIntensity);
    // Either first bounce (first_bounce): the roulette keeps rho of the photons at their power,
    // the weighted one all of them at rho times it; the same stored power in expectation.
    for (const char* firstBounce : {"roulette", "weighted"}) {
        for (int bounces : {1, 3}) {
            Settings settings = makeTestSettings({{"first_bounce", firstBounce},
                                                  {"width", 16},
                                                  {"height", 16},
                                                  {"shadow_map_size", 128},
                                                  {"photons", kPhotons},
                                                  {"bounces", bounces},
                                                  {"seed", 3}});
            FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
            runner.renderFrame();
            const PhotonCounts counts = readPhotonCounts(runner);
            ASSERT_EQ(counts.overflow, 0u);
            ASSERT_GT(counts.stored, 0u);
            const auto photons =
                runner.getPasses().photons.getResult().read<gpu::ResultPhoton>(counts.stored);
            glm::dvec3 stored(0.0);
            for (const gpu::ResultPhoton& p : photons)
                stored += glm::dvec3(glm::vec3(p.power));
            double series = 0.0;
            for (int k = 1; k <= bounces; ++k)
                series += std::pow(double(kRho), k);
            const double expected = lightPower * series;
            std::printf(
                "first bounce %s, bounces %d: stored/expected = %.4f %.4f %.4f (%u photons)\n",
                firstBounce, bounces, stored.x / expected, stored.y / expected, stored.z / expected,
                counts.stored);
            // 2%: Russian roulette with ~50k photons has a relative standard deviation of about
            // sqrt((1 - rho) / (rho N)) ~ 0.4% per bounce, the importance maps' weights about
            // 0.5% (ImportanceKeepsEmittedPowerInExpectation; measured 1.0017 and 1.0065 at one
            // bounce); a missing bounce or a wrong power scale is off by 20% or more.
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(stored[c] / expected, 1.0, 0.02)
                    << firstBounce << ", bounces " << bounces << " channel " << c;
            }
        }
    }
}

// Pixel footprint on the plane y = 0: exact, from the pixel's corners projected onto the plane.
double computePixelArea(const Scene& scene, int x, int y, int size) {
    const double fx = x;
    const double fy = y;
    const glm::dvec3 c00 = projectToGround(scene, size, size, fx, fy);
    const glm::dvec3 c10 = projectToGround(scene, size, size, fx + 1.0, fy);
    const glm::dvec3 c01 = projectToGround(scene, size, size, fx, fy + 1.0);
    const glm::dvec3 c11 = projectToGround(scene, size, size, fx + 1.0, fy + 1.0);
    return 0.5 * glm::length(glm::cross(c11 - c00, c01 - c10));
}

// Both splat shapes and the tiled gather: the flat square, the thesis's squashed box and the
// gather's tiles shade the same pixels of a plane, so each conserves the photon's power there.
class SplatShapeEnergyTest : public PhotonEnergyTest,
                             public ::testing::WithParamInterface<const char*> {};

TEST_P(SplatShapeEnergyTest, OneSplatOnAPlaneIntegratesToBrdfTimesPower) {
    constexpr float kRho = 0.5f;
    constexpr int kSize = 128;
    constexpr float kRadiusM = 0.3f; // ~40 pixels across: the kernel is well resolved
    // The plane's own light is left out: the frame below stores no photons (bounces = 0).
    Scene scene = makeLitPlane(kRho, 0.0f, 1.0f, 5.0f);
    // Far and narrow: close to the orthographic camera the closed form assumes; the pixel areas
    // below are exact anyway.
    scene.camera.position = {0.0f, 20.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.fovYDeg = 3.0f;
    Settings settings = makeTestSettings({{"width", kSize}, {"height", kSize}});
    settings.set("bounces", 0, "test"); // the frame itself stores no photons
    settings = withSettings(settings, {{"radius_min", kRadiusM}, {"radius_max", kRadiusM}});
    settings.setEnum("radius_mode", "travel", "test"); // the radius set above, not the density's
    if (std::string(GetParam()) == "gather") {
        settings.setEnum("splat_mode", "gather", "test");
    } else {
        settings.setEnum("splat_shape", GetParam(), "test");
    }
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();

    // One photon of 1 W at the origin, arriving straight down.
    PhotonBuffers buffers;
    buffers.reserve(1, 1);
    gpu::ResultPhoton photon{};
    photon.positionDistance = glm::vec4(0.1f, 0.0f, -0.05f, 1.0f);
    photon.normalDensity = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    photon.incoming = glm::vec4(0.0f, -1.0f, 0.0f, 1.0f);
    // w: the radius the density pass gives every photon in the travel modes (radius_min =
    // radius_max), here without that pass.
    photon.power = glm::vec4(1.0f, 2.0f, 0.5f, kRadiusM);
    buffers.getResult().upload(0, sizeof(photon), &photon);
    gpu::PhotonCounters counters{};
    counters.result = glm::uvec4(1, 1, 0, 1);
    const uint32_t indices = gpu::getSplatIndexCount(runner.getFrameInputs().settings.splatShape);
    counters.splatDraw = glm::uvec4(indices, 1, 0, 0);
    buffers.getCounters().upload(0, sizeof(counters), &counters);
    const glm::uvec4 draw[gpu::kSplatDrawUvec4s] = {{indices, 1, 0, 0}, {0, 0, 0, 0}};
    buffers.getSplatDraws().upload(0, sizeof(draw), draw);

    const PhotonDensityPass density(
        buffers, runner.getPasses()
                     .gbuffer.getGBuffer()); // travel radii: the splat reads none of its buffers
    SplatPass splat(runner.getPasses().gbuffer.getGBuffer(), buffers, density);
    splat.resize(kSize, kSize);
    splat.execute(runner.getFrameInputs());
    const std::vector<glm::vec4> radiance = splat.getOutput().readRgba();

    glm::dvec3 flux(0.0);
    int covered = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec4 L = radiance[size_t(y * kSize + x)];
            if (L.x > 0.0f) ++covered;
            // GL rows start at the bottom; projectToGround counts rows from the top.
            flux += glm::dvec3(glm::vec3(L)) * computePixelArea(scene, x, kSize - 1 - y, kSize);
        }
    }
    EXPECT_GT(covered, 1000) << "the splat covers a disc of many pixels";
    std::printf("splat: %d pixels, flux / expected = %.5f\n", covered,
                flux.x / (double(kRho) / glm::pi<double>()));
    // Integral of radiance over area = BRDF x power = rho / pi x power (W/sr). 1%: the kernel is
    // sampled at pixel centres; at ~40 pixels across a disc, the sum errs by well under 1%.
    const glm::dvec3 expected =
        glm::dvec3(glm::vec3(photon.power)) * double(kRho) / glm::pi<double>();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(flux[c] / expected[c], 1.0, 0.01) << "channel " << c;
}

INSTANTIATE_TEST_SUITE_P(Shapes, SplatShapeEnergyTest, ::testing::Values("disc", "box", "gather"));

} // namespace
} // namespace ispm::test
