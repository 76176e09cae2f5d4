// Shadows by ray (setting shadows ray): a square floating over a lit plane under a slanted sun
// casts exactly the shadow its outline projects, pixel by pixel; the light views then only emit
// photons, so their size follows the photon budget (computeShadowMapSize). With edge_samples the
// pixels the shadow's edge crosses get the mean over their area, as the closed form integrated
// over each pixel; and so do the pixels at a silhouette, a sliver of a farther surface that no
// pixel's centre shows included.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "image/metrics.h"
#include "settings/frame_settings.h"
#include "support/test_settings.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <tuple>
#include <utility>

namespace ispm::test {
namespace {

constexpr int kSize = 64;
constexpr float kRho = 0.5f;
constexpr float kIrradiance = 10.0f; // W/m^2 facing the sun
constexpr float kSquareHeightM = 0.5f;
constexpr float kSquareHalfM = 0.3f;
const glm::vec3 kSunDirection = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));

Scene makeShadowScene() {
    Scene scene = makeLitPlane(kRho, 1.0f, 2.0f, 10.0f);
    scene.lights[0].type = LightType::Sun;
    scene.lights[0].direction = kSunDirection;
    scene.lights[0].irradiance = glm::vec3(kIrradiance);
    scene.lights[0].intensity = glm::vec3(0.0f);
    Mesh square;
    square.name = "occluder";
    const float s = kSquareHalfM;
    const float h = kSquareHeightM;
    square.positions = {{-s, h, -s}, {s, h, -s}, {s, h, s}, {-s, h, s}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    square.triangleMaterials = {0, 0};
    scene.meshes.push_back(square);
    scene.instances.push_back({1, glm::mat4(1.0f)});
    scene.camera.position = {0.0f, 2.5f, 2.2f};
    scene.camera.target = {0.2f, 0.0f, -0.1f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.fovYDeg = 50.0f;
    return scene;
}

// Where on the square's plane (y = kSquareHeightM) the ray from `from` along `dir` arrives, as
// the largest of |x|, |z| over the square's half size (below 1: inside); none when it does not
// reach that plane.
std::optional<double> measureSquareReach(const glm::dvec3& from, const glm::dvec3& dir) {
    if (std::abs(dir.y) < 1e-12) return std::nullopt;
    const double t = (double(kSquareHeightM) - from.y) / dir.y;
    if (t <= 0.0) return std::nullopt;
    const glm::dvec3 p = from + dir * t;
    return std::max(std::abs(p.x), std::abs(p.z)) / double(kSquareHalfM);
}

// The ground's radiance where the sun reaches it (the square's top alike): rho / pi E cos.
double computeLitRadiance() {
    return double(kRho) / std::numbers::pi * double(kIrradiance) * -double(kSunDirection.y);
}

struct ShadowCount {
    int shadowed = 0;
    int lit = 0;
    int wrong = 0;
};

// Every pixel whose centre sees the ground (not the square) against the closed form: zero where
// the ray from its ground point toward the sun meets the square, rho / pi * E * cos(theta)
// elsewhere.
ShadowCount compareWithClosedForm(const Scene& scene, const Image& image) {
    const glm::dvec3 eye(scene.camera.position);
    const glm::dvec3 toSun = -glm::dvec3(kSunDirection);
    const double litRadiance = computeLitRadiance();
    // Pixels whose ground point lies this close to the shadow's outline (in half sizes of the
    // square: 2 mm) are left out: positions are stored as float, which moves the edge by ~1e-6 m.
    constexpr double kEdgeMargin = 0.007;
    ShadowCount count;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 ground = projectToGround(scene, kSize, kSize, x + 0.5, y + 0.5);
            const std::optional<double> seen = measureSquareReach(eye, ground - eye);
            if (seen && *seen < 1.0 + kEdgeMargin) continue; // the square, or its rim, is in front
            const std::optional<double> reach = measureSquareReach(ground, toSun);
            if (reach && std::abs(*reach - 1.0) < kEdgeMargin) continue;
            const bool inShadow = reach && *reach < 1.0;
            const double expected = inShadow ? 0.0 : litRadiance;
            const glm::vec3 got = image.at(x, y);
            // Lit: float positions and normals, 1e-3 relative; shadowed: exactly zero.
            const bool right = inShadow ? got == glm::vec3(0.0f)
                                        : std::abs(double(got.x) - expected) < 1e-3 * expected;
            (inShadow ? count.shadowed : count.lit)++;
            if (!right) ++count.wrong;
        }
    }
    return count;
}

class ShadowRaysTest : public GlTest {};

// kSize x kSize, shadows by ray, `edgeSamples` edge samples.
Settings makeRaySettings(int edgeSamples) {
    Settings settings = makeTestSettings(
        {{"width", kSize}, {"height", kSize}, {"shadows", "ray"}, {"edge_samples", edgeSamples}});
    return settings;
}

TEST_F(ShadowRaysTest, SquareCastsItsExactShadow) {
    const Scene scene = makeShadowScene();
    Settings settings = makeRaySettings(0); // each pixel's centre, as the closed form above
    // Coarse light views: rays do not look at them, a shadow map's edge steps by their texels.
    settings.set("shadow_map_size", 64, "test");
    const ShadowCount ray = compareWithClosedForm(scene, renderAov(scene, settings, Aov::Direct));
    // Both sides of the edge were seen: not a black image, not a shadowless one.
    EXPECT_GT(ray.shadowed, 100);
    EXPECT_GT(ray.lit, 1000);
    EXPECT_EQ(ray.wrong, 0) << "of " << ray.shadowed << " shadowed and " << ray.lit << " lit";

    // The same views as shadow maps put pixels on the wrong side of the edge: the rays above
    // were traced, not read from the maps.
    settings.setEnum("shadows", "map", "test");
    const ShadowCount map = compareWithClosedForm(scene, renderAov(scene, settings, Aov::Direct));
    std::printf("pixels off the closed form at 64x64 light texels: shadow map %d, shadow rays %d "
                "(of %d)\n",
                map.wrong, ray.wrong, map.shadowed + map.lit);
    EXPECT_GT(map.wrong, 0);
}

// The share of pixel (x, y) (top-left origin) whose view reaches a lit point: the square's top,
// or the ground where the square does not shade it; from kSubSamples x kSubSamples points of the
// closed form.
double computeLitShare(const Scene& scene, int x, int y) {
    constexpr int kSubSamples = 32;
    const glm::dvec3 eye(scene.camera.position);
    const glm::dvec3 toSun = -glm::dvec3(kSunDirection);
    int lit = 0;
    for (int j = 0; j < kSubSamples; ++j) {
        for (int i = 0; i < kSubSamples; ++i) {
            const glm::dvec3 ground = projectToGround(
                scene, kSize, kSize, x + (i + 0.5) / kSubSamples, y + (j + 0.5) / kSubSamples);
            const std::optional<double> seen = measureSquareReach(eye, ground - eye);
            const std::optional<double> reach = measureSquareReach(ground, toSun);
            if ((seen && *seen < 1.0) || !(reach && *reach < 1.0)) ++lit;
        }
    }
    return double(lit) / double(kSubSamples * kSubSamples);
}

struct EdgeError {
    int pixels = 0;        // pixels the shadow's edge crosses (lit share strictly between 0 and 1)
    double meanError = 0;  // mean |direct - lit share x lit radiance| over them, / lit radiance
    double worstError = 0; // the largest of them
    // The rel MSE's view (image/metrics.h): |direct - exact| / sqrt(exact^2 + epsilon), the mean
    // over the pixels; edge_shade.comp spends its samples to even this out.
    double meanRelative = 0;
};

EdgeError measureEdgeError(const Scene& scene, const Image& image) {
    const double litRadiance = computeLitRadiance();
    EdgeError e;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const double share = computeLitShare(scene, x, y);
            if (share <= 0.0 || share >= 1.0) continue;
            const double error = std::abs(double(image.at(x, y).x) / litRadiance - share);
            const double exact = share * litRadiance;
            ++e.pixels;
            e.meanError += error;
            e.meanRelative += error * litRadiance / std::sqrt(exact * exact + kRelMseEpsilon);
            e.worstError = std::max(e.worstError, error);
        }
    }
    if (e.pixels > 0) {
        e.meanError /= e.pixels;
        e.meanRelative /= e.pixels;
    }
    return e;
}

TEST_F(ShadowRaysTest, EdgeSamplesAverageThePixel) {
    const Scene scene = makeShadowScene();
    Settings settings = makeRaySettings(0);
    const EdgeError centre = measureEdgeError(scene, renderAov(scene, settings, Aov::Direct));
    settings.set("edge_samples", 64, "test");
    const EdgeError averaged = measureEdgeError(scene, renderAov(scene, settings, Aov::Direct));
    std::printf("shadow edge pixels (%d): mean / worst error of the lit share, pixel centres "
                "%.3f / %.3f, 64 edge samples %.3f / %.3f; mean relative error %.3f / %.3f\n",
                averaged.pixels, centre.meanError, centre.worstError, averaged.meanError,
                averaged.worstError, centre.meanRelative, averaged.meanRelative);
    // The shadow's edge is long enough to measure: two sides of a 0.6 m square at 64 px.
    EXPECT_GT(averaged.pixels, 30);
    // A centre sample is all or nothing: a quarter of the contrast off on average for an edge
    // at a random place in the pixel (measured 0.19). 64 samples of a (0,2)-sequence along a
    // straight edge err by about 1/64 to 1/8 of the contrast (the edge's slope against the
    // strata), 32 by up to twice that: the pixels lit over about a third take 32 (their light's
    // spread is under 3x their own, edge_find.comp), the darker 64 (measured 0.016 mean, 0.057
    // worst; 0.010 / 0.038 with 64 everywhere). A pixel the edge only grazes at a corner could be
    // missed by edge_find.comp and keep its centre's value, a sliver's share at most.
    EXPECT_GT(centre.meanError, 0.12);
    EXPECT_LT(averaged.meanError, 0.03);
    EXPECT_LT(averaged.worstError, 0.15);
    // The same as rel MSE weighs it (error over sqrt(exact^2 + epsilon)): the halved pixels are
    // the bright ones, where it counts least (measured 0.045; 0.037 with 64 everywhere, 0.506 at
    // the centres).
    EXPECT_LT(averaged.meanRelative, 0.08);
}

// Two sunlit walls facing the camera, against a black background: the near one's right edge
// 5% into pixel column kSliverColumn, the far one, behind it, reaching 45% into that column, so
// that no pixel's centre shows the far wall; the sun shines along the view, so the near wall's
// shadow on the far one stays behind it.
constexpr int kSliverColumn = 40;
constexpr double kNearEdgePx = kSliverColumn + 0.05;
constexpr double kFarEdgePx = kSliverColumn + 0.45;
constexpr float kNearRho = 0.3f;
constexpr float kFarRho = 0.8f;
constexpr double kNearZ = 0.0;
constexpr double kFarZ = -1.0;

Scene makeSliverScene() {
    Scene scene;
    scene.sourcePath = "sliver behind a silhouette";
    for (const auto& [name, rho] : {std::pair{"near", kNearRho}, std::pair{"far", kFarRho}}) {
        Material m;
        m.name = name;
        m.diffuse = glm::vec3(rho);
        scene.materials.push_back(m);
    }
    scene.camera.position = {0.0f, 0.0f, 3.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.fovYDeg = 40.0f;
    Light sun;
    sun.type = LightType::Sun;
    sun.direction = {0.0f, 0.0f, -1.0f};
    sun.irradiance = glm::vec3(kIrradiance);
    scene.lights.push_back(sun);
    // Each wall from x = -2 to where its edge projects to the image position above.
    const double tanHalf = std::tan(glm::radians(20.0));
    const auto edgeX = [&](double px, double z) {
        return (px / kSize * 2.0 - 1.0) * tanHalf * (double(scene.camera.position.z) - z);
    };
    for (const auto& [px, z, material] :
         {std::tuple{kNearEdgePx, kNearZ, 0u}, std::tuple{kFarEdgePx, kFarZ, 1u}}) {
        const float x = float(edgeX(px, z));
        Mesh wall;
        wall.name = material == 0u ? "near wall" : "far wall";
        wall.positions = {{-2.0f, -1.0f, float(z)},
                          {x, -1.0f, float(z)},
                          {x, 1.0f, float(z)},
                          {-2.0f, 1.0f, float(z)}};
        wall.triangles = {{0, 1, 2}, {0, 2, 3}};
        wall.triangleMaterials = {material, material};
        scene.meshes.push_back(wall);
        scene.instances.push_back({uint32_t(scene.meshes.size() - 1), glm::mat4(1.0f)});
    }
    return scene;
}

// The mean radiance over pixel (x, y) (top-left origin), from camera rays through kColumns x
// kRows points of it met with the two walls: rho / pi x E on either (the sun straight on), 0
// past them. The edges run along y: 512 columns place them to 1/512 of a pixel.
double computeSliverPixel(const Scene& scene, int x, int y) {
    constexpr int kColumns = 512;
    constexpr int kRows = 4;
    double sum = 0.0;
    for (int j = 0; j < kRows; ++j) {
        for (int i = 0; i < kColumns; ++i) {
            const ViewRay ray = computeViewRay(scene, kSize, kSize, x + (i + 0.5) / kColumns,
                                               y + (j + 0.5) / kRows);
            for (const auto& [z, rho] : {std::pair{kNearZ, kNearRho}, std::pair{kFarZ, kFarRho}}) {
                const glm::dvec3 p = ray.origin + ray.dir * ((z - ray.origin.z) / ray.dir.z);
                const glm::dvec3 corner = scene.meshes[z == kNearZ ? 0 : 1].positions[2];
                if (p.x >= -2.0 && p.x <= corner.x && std::abs(p.y) <= 1.0) {
                    sum += double(rho) / std::numbers::pi * double(kIrradiance);
                    break; // the near wall first: it hides the far one
                }
            }
        }
    }
    return sum / double(kColumns * kRows);
}

TEST_F(ShadowRaysTest, EdgeSamplesSeeASliverBeyondASilhouette) {
    const Scene scene = makeSliverScene();
    const Image image = renderAov(scene, makeRaySettings(64), Aov::Direct);
    // The rows well inside both walls (they span rows 3-61).
    double got = 0.0;
    double expected = 0.0;
    double nearOnly = 0.0;
    for (int y = 16; y < 48; ++y) {
        got += double(image.at(kSliverColumn, y).x);
        expected += computeSliverPixel(scene, kSliverColumn, y);
        nearOnly += 0.05 * double(kNearRho) / std::numbers::pi * double(kIrradiance);
        // The columns beside it: the near wall whole, the background.
        EXPECT_NEAR(image.at(kSliverColumn - 1, y).x,
                    double(kNearRho) / std::numbers::pi * double(kIrradiance), 1e-3);
        EXPECT_EQ(image.at(kSliverColumn + 1, y).x, 0.0f);
    }
    std::printf("sliver column: %.3f of the closed form's %.3f (the near wall's 5%% alone: %.3f)\n",
                got, expected, nearOnly);
    // The far wall's sliver is most of the column's light (0.4 x 0.8 against 0.05 x 0.3): rays
    // that looked only for the instances the neighbouring pixels show would leave 4% of it.
    // 64 samples of a (0,2)-sequence place the sliver's two straight edges to within 1/64 of a
    // pixel, a random place in that stratum each row: over 32 rows within 2% (measured 0.2%).
    EXPECT_NEAR(got / expected, 1.0, 0.02);
}

TEST(ShadowMapSize, FollowsTheShadowMode) {
    Settings s;
    EXPECT_EQ(computeShadowMapSize(s), 1024); // shadow maps need their texels
    s = withSettings(s, {{"shadows", "ray"}, {"photons", 10000}});
    EXPECT_EQ(computeShadowMapSize(s), 256); // 2 sqrt(10,000) = 200
    s.set("photons", 25000, "test");
    EXPECT_EQ(computeShadowMapSize(s), 512); // 316
    s.set("photons", 50000, "test");
    EXPECT_EQ(computeShadowMapSize(s), 512); // 447
    s.set("photons", 100000, "test");
    EXPECT_EQ(computeShadowMapSize(s), 1024); // 632
    s.set("photons", 4000000, "test");
    EXPECT_EQ(computeShadowMapSize(s), 1024); // at most what shadow maps get
    s.set("photons", 0, "test");
    EXPECT_EQ(computeShadowMapSize(s), 256);
    s.set("shadow_map_size", 100, "test"); // a set size is taken as it is
    EXPECT_EQ(computeShadowMapSize(s), 100);
    EXPECT_EQ(resolveFrameSettings(s).shadowMapSize, 100);
}

} // namespace
} // namespace ispm::test
