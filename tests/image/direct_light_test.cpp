// Analytic render tests of direct light: energy and units errors show here before any golden.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "render/frame_constants.h"
#include "render/light_cameras.h"
#include "render/pixel_rect.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace ispm::test {
namespace {

class DirectLightTest : public GlTest {};

TEST_F(DirectLightTest, PointLightOverDiffusePlaneMatchesClosedForm) {
    constexpr float kRho = 0.5f;
    constexpr float kIntensity = 10.0f; // W/sr
    constexpr float kHeight = 1.0f;     // m
    constexpr float kPlaneHalf = 10.0f; // much wider than the view: no edge in the image
    constexpr int kSize = 64;
    Scene scene = makeLitPlane(kRho, kIntensity, kHeight, kPlaneHalf);
    scene.camera.position = {0.3f, 3.0f, 0.2f};
    scene.camera.target = {0.3f, 0.0f, 0.2f};
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.fovYDeg = 60.0f;
    Settings settings = makeTestSettings({{"width", kSize}, {"height", kSize}});
    const Image image = renderAov(scene, settings, Aov::Direct);

    int checked = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 p = projectToGround(scene, kSize, kSize, x + 0.5, y + 0.5);
            const auto expected = float(computePlaneRadiance(kRho, kIntensity, kHeight, p));
            const glm::vec3 actual = image.at(x, y);
            // 1%: the G-buffer stores positions in 32-bit float and normals in 16-bit float
            // (relative error ~1e-3); the radiometry itself must be exact.
            constexpr float kTolerance = 0.01f;
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(actual[c], expected, kTolerance * expected)
                    << "pixel " << x << "," << y << " channel " << c;
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, kSize * kSize);
}

TEST_F(DirectLightTest, SpotLightShadedOverItsPoolMatchesClosedForm) {
    // A spot light's pool covers a tenth of the image: the direct pass shades it in a draw over
    // the pool's pixels alone (computeLitBounds, computePixelRect). Inside, the point light's
    // closed form times the spot falloff; outside, exactly nothing.
    constexpr float kRho = 0.5f;
    constexpr float kIntensity = 10.0f; // W/sr on the axis
    constexpr float kHeight = 1.0f;     // m
    constexpr int kSize = 64;
    Scene scene = makeLitPlane(kRho, kIntensity, kHeight, 10.0f);
    Light& spot = scene.lights[0];
    spot.type = LightType::Spot;
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.innerDeg = 15.0f;
    spot.outerDeg = 30.0f;
    scene.camera.position = {0.3f, 3.0f, 0.2f};
    scene.camera.target = {0.3f, 0.0f, 0.2f};
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.fovYDeg = 60.0f;

    // The test covers the pool's own draw: its pixels are well under the direct pass's share
    // for a whole-image draw (kWholeImageShare, 0.5).
    float nearM = 0.0f;
    float farM = 0.0f;
    computeCameraRange(scene.camera, scene.computeWorldBounds(), scene.computeInstanceBounds(),
                       nearM, farM);
    const glm::mat4 clipFromWorld =
        computeClipFromView(scene.camera, 1.0f, nearM, farM) * computeViewFromWorld(scene.camera);
    const std::optional<Aabb> lit = computeLitBounds(spot, scene.computeWorldBounds());
    ASSERT_TRUE(lit.has_value());
    const std::optional<PixelRect> rect = computePixelRect(*lit, clipFromWorld, kSize, kSize);
    ASSERT_TRUE(rect.has_value());
    EXPECT_LT(rect->getArea(), 0.25 * kSize * kSize);

    Settings settings = makeTestSettings({{"width", kSize}, {"height", kSize}});
    const Image image = renderAov(scene, settings, Aov::Direct);
    const double peak = computePlaneRadiance(kRho, kIntensity, kHeight, glm::dvec3(0.0));
    int inside = 0;
    int outside = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 p = projectToGround(scene, kSize, kSize, x + 0.5, y + 0.5);
            const double cosAngle =
                double(kHeight) / glm::length(glm::dvec3(0.0, kHeight, 0.0) - p);
            const double falloff =
                computeSpotFalloff(float(cosAngle), spot.innerDeg, spot.outerDeg);
            const auto expected =
                float(computePlaneRadiance(kRho, kIntensity, kHeight, p) * falloff);
            // 1% of the pool's peak: positions and normals are stored in float (relative error
            // ~1e-3), which moves the steep falloff between the cones by that much.
            const auto tolerance = float(0.01 * peak);
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(image.at(x, y)[c], expected, tolerance)
                    << "pixel " << x << "," << y << " channel " << c;
            }
            if (falloff > 0.5) ++inside;
            if (falloff == 0.0) {
                ++outside;
                EXPECT_EQ(image.at(x, y), glm::vec3(0.0f)) << "pixel " << x << "," << y;
            }
        }
    }
    // Both sides were seen: the pool is lit (not a black image), and most of the plane is not.
    EXPECT_GT(inside, 50);
    EXPECT_GT(outside, kSize * kSize / 2);
}

TEST_F(DirectLightTest, OccluderCastsFullShadow) {
    // A small box between the light and the plane: the point under it gets no direct light.
    Scene scene = makeLitPlane(0.5f, 10.0f, 2.0f, 10.0f);
    Mesh box;
    box.name = "occluder";
    const float s = 0.2f;
    box.positions = {{-s, 0.9f, -s}, {s, 0.9f, -s}, {s, 0.9f, s}, {-s, 0.9f, s}};
    box.triangles = {{0, 1, 2}, {0, 2, 3}};
    box.triangleMaterials = {0, 0};
    scene.meshes.push_back(box);
    scene.instances.push_back({1, glm::mat4(1.0f)});
    scene.camera.position = {0.0f, 0.5f, 0.0f}; // under the occluder, looking down
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.fovYDeg = 20.0f;
    Settings settings = makeTestSettings({{"width", 16}, {"height", 16}});
    const Image image = renderAov(scene, settings, Aov::Direct);
    for (const glm::vec3& p : image.pixels)
        EXPECT_EQ(p, glm::vec3(0.0f));

    // Without the occluder the same view is lit: the zero above is a shadow, not a black image.
    scene.instances.pop_back();
    const Image lit = renderAov(scene, settings, Aov::Direct);
    for (const glm::vec3& p : lit.pixels)
        EXPECT_GT(p.x, 0.0f);
}

TEST_F(DirectLightTest, CornellBoxMatchesGolden) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    Settings settings = withSettings(scene.settings, {{"width", 128}, {"height", 128}});
    settings.set("bounces", 0, "test"); // direct light only
    // A fixed white point (about the 99th percentile of luminance the derived one picks): one
    // derived from the image would cancel a scale error of the whole image.
    constexpr double kWhitePoint = 1.27; // W/(m^2 sr)
    settings.set("luminance_max", kWhitePoint, "test");
    const Image display = renderAov(scene, settings, Aov::Display);
    // Tone-mapped 8-bit values. Another GL implementation rasterises edges and rounds shadow
    // comparisons slightly differently: allow 2/255 on average and 1% of pixels off by more
    // than 8/255 (edge pixels of the blocks and shadow boundaries); a wrong light, material or
    // shadow moves far more pixels than that.
    expectMatchesGolden(display, "cornell_direct", {8.0f / 255.0f, 2.0f / 255.0f, 0.01});
    // Not black: the golden itself could be wrong, so check content too.
    double sum = 0.0;
    for (const glm::vec3& p : display.pixels)
        sum += double(p.x + p.y + p.z);
    EXPECT_GT(sum / (3.0 * static_cast<double>(display.pixels.size())), 0.05);
}

} // namespace
} // namespace ispm::test
