// Indirect light end to end: goldens of the Cornell box and box city with photons, and the
// Cornell ceiling, which the spotlight never reaches, lit by bounced light alone.
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "scene/scene_loader.h"
#include "support/test_settings.h"

namespace ispm::test {
namespace {

class IndirectTest : public GlTest {};

constexpr double kCornellWhite = 0.87;  // W/(m^2 sr)
constexpr double kBoxCityWhite = 176.0; // W/(m^2 sr)

Settings makeSettings(const Scene& scene, int size) {
    Settings settings = withSettings(scene.settings, {{"width", size}, {"height", size}});
    settings.set("photons", 20000, "test"); // small enough for llvmpipe, enough to be stable
    settings = withSettings(settings, {{"shadow_map_size", 256}, {"seed", 1}});
    return settings;
}

// Photons are appended by many threads, so the splat order (and float rounding of the sum)
// varies between runs and GL implementations; and a photon's random path can change when a hit
// moves by one ulp. Allow 3/255 on average and 2% of pixels off by more than 12/255; missing or
// doubled indirect light, or a wrong colour, moves far more.
constexpr GoldenThresholds kIndirectThresholds{12.0f / 255.0f, 3.0f / 255.0f, 0.02};

// Goldens are tone mapped with a fixed white point per scene (about the 99th percentile of
// luminance that the derived one picks): a white point derived from the image would cancel a
// scale error of the whole image, which must fail the golden instead.
Settings makeGoldenSettings(const Scene& scene, double whitePoint) {
    Settings settings = withSettings(makeSettings(scene, 128), {{"luminance_max", whitePoint}});
    return settings;
}

TEST_F(IndirectTest, CornellBoxMatchesGolden) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    expectMatchesGolden(renderAov(scene, makeGoldenSettings(scene, kCornellWhite), Aov::Display),
                        "cornell_total", kIndirectThresholds);
}

TEST_F(IndirectTest, BoxCityMatchesGolden) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/box_city.json");
    expectMatchesGolden(renderAov(scene, makeGoldenSettings(scene, kBoxCityWhite), Aov::Display),
                        "box_city_total", kIndirectThresholds);
}

TEST_F(IndirectTest, CornellCeilingIsLitOnlyByBouncedLight) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    const Settings settings = makeSettings(scene, 64);
    const Image direct = renderAov(scene, settings, Aov::Direct);
    const Image indirect = renderAov(scene, settings, Aov::Indirect);
    // The top rows of the image show the ceiling; the spot points down from just below it.
    constexpr int kCeilingRows = 4;
    double directSum = 0.0;
    double indirectSum = 0.0;
    int lit = 0;
    for (int y = 0; y < kCeilingRows; ++y) {
        for (int x = direct.width / 4; x < 3 * direct.width / 4; ++x) {
            directSum += double(direct.at(x, y).x);
            indirectSum += double(indirect.at(x, y).x);
            lit += indirect.at(x, y).x > 0.0f;
        }
    }
    EXPECT_EQ(directSum, 0.0) << "no direct light reaches the ceiling";
    const int pixels = kCeilingRows * direct.width / 2;
    // With 20k photons the ceiling, reached only by bounced photons, is sparse: a quarter of its
    // pixels fall between splats at this budget (measured 96 of 128). Most must be covered.
    EXPECT_GE(lit, pixels * 7 / 10) << "ceiling pixels receiving photons";
    // Bounced light on the ceiling: of the order of the floor's direct light times the wall
    // albedo and the form factor; at least a percent of the brightest direct pixel.
    float maxDirect = 0.0f;
    for (const glm::vec3& p : direct.pixels)
        maxDirect = std::max(maxDirect, p.x);
    EXPECT_GT(indirectSum / pixels, 0.01 * double(maxDirect));
}

TEST_F(IndirectTest, BouncesZeroMeansNoIndirectLight) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    Settings settings = withSettings(makeSettings(scene, 32), {{"bounces", 0}});
    for (const glm::vec3& p : renderAov(scene, settings, Aov::Indirect).pixels) {
        EXPECT_EQ(p, glm::vec3(0.0f));
    }
    // and total = direct + indirect when there is indirect light
    settings.set("bounces", 2, "test");
    const Image direct = renderAov(scene, settings, Aov::Direct);
    const Image indirect = renderAov(scene, settings, Aov::Indirect);
    const Image total = renderAov(scene, settings, Aov::Total);
    for (size_t i = 0; i < total.pixels.size(); ++i) {
        const glm::vec3 sum = direct.pixels[i] + indirect.pixels[i];
        // Float sums of the same values; a photon splat order change moves the last bits only.
        EXPECT_NEAR(total.pixels[i].x, sum.x, 1e-4f * std::max(1.0f, sum.x)) << i;
    }
}

} // namespace
} // namespace ispm::test
