// The photon-buffer images (`render --aov bounce_direction ...`, the viewer's photon points), in
// the Cornell box lit by its ceiling spot: drawn by direction, result photons arrive downwards on
// the floor and upwards at the ceiling, and bounce photons leave the floor upwards; drawn by
// power, photons take the colour of the wall they left and sit on the stated scale.
#include "support/gl_fixture.h"

#include "render/photon_points.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <cmath>
#include <memory>

namespace ispm::test {
namespace {

class PhotonPointsTest : public GlTest {};

constexpr int kSize = 96;
constexpr int kPhotons = 20000;
constexpr float kGamma = 2.2f; // power colours' encoding (photon_points.cpp)

struct CornellFrame {
    Scene scene;
    std::unique_ptr<FrameRunner> runner;
};

CornellFrame renderCornell() {
    CornellFrame f{.scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json")};
    Settings s = withSettings(f.scene.settings,
                              {{"width", kSize}, {"height", kSize}, {"photons", kPhotons}});
    f.runner = std::make_unique<FrameRunner>(f.scene, s, gl::TimingMethod::CpuFinish);
    f.runner->renderFrame();
    return f;
}

// The mean colour of the points (non-black pixels: no direction or power colour in these
// scenes is black) in a block of the image given as fractions of its size, row 0 at the top.
struct PointsMean {
    glm::dvec3 colour{0.0};
    int points = 0;
};
PointsMean averagePoints(const Image& image, double x0, double x1, double y0, double y1) {
    PointsMean mean;
    const auto to = [](double f, int n) { return static_cast<int>(f * n); };
    for (int y = to(y0, image.height); y < to(y1, image.height); ++y) {
        for (int x = to(x0, image.width); x < to(x1, image.width); ++x) {
            const glm::vec3 c = image.at(x, y);
            if (c.x + c.y + c.z <= 0.0f) continue;
            mean.colour += glm::dvec3(c);
            ++mean.points;
        }
    }
    if (mean.points > 0) mean.colour /= double(mean.points);
    return mean;
}

// Blocks of the 96x96 Cornell view that only floor, ceiling or one wall fill (the blocks stand
// between x 0.3 and 0.75, below y 0.4).
constexpr double kCeiling[] = {0.3, 0.7, 0.02, 0.15};
constexpr double kFloor[] = {0.05, 0.25, 0.9, 0.98};
constexpr double kRedWall[] = {0.01, 0.12, 0.55, 0.85};
constexpr double kGreenWall[] = {0.88, 0.99, 0.55, 0.85};

PointsMean averagePoints(const Image& image, const double (&block)[4]) {
    return averagePoints(image, block[0], block[1], block[2], block[3]);
}

// Enough points that the means below are not one photon's (a block holds hundreds).
constexpr int kMinPoints = 20;
// Direction colours are 0.5 + y / 2: an average direction at least 0.2 up (or down) shows as
// 0.6 (0.4). Diffuse directions average y = 2/3 about the normal; travel onto the floor and
// ceiling is mostly vertical.
constexpr double kUp = 0.6;
constexpr double kDown = 0.4;

TEST_F(PhotonPointsTest, DirectionShowsWherePhotonsGo) {
    const CornellFrame f = renderCornell();
    const PhotonPointsDrawer drawer;
    const Image result = drawer.renderAov(
        *f.runner, {.points = PhotonPoints::Result, .colour = PhotonColour::Direction}, false);
    const PointsMean ceiling = averagePoints(result, kCeiling);
    const PointsMean floor = averagePoints(result, kFloor);
    ASSERT_GE(ceiling.points, kMinPoints);
    ASSERT_GE(floor.points, kMinPoints);
    EXPECT_GT(ceiling.colour.y, kUp) << "result photons reach the ceiling travelling up";
    EXPECT_LT(floor.colour.y, kDown) << "result photons reach the floor travelling down";

    const Image bounce = drawer.renderAov(
        *f.runner, {.points = PhotonPoints::Bounce, .colour = PhotonColour::Direction}, false);
    const PointsMean leaving = averagePoints(bounce, kFloor);
    ASSERT_GE(leaving.points, kMinPoints);
    EXPECT_GT(leaving.colour.y, kUp) << "bounce photons leave the floor upwards";
    // The spot lights the floor first: no first-bounce photon leaves the ceiling.
    EXPECT_EQ(averagePoints(bounce, kCeiling).points, 0);
}

TEST_F(PhotonPointsTest, PowerTakesTheWallsColourOnTheStatedScale) {
    const CornellFrame f = renderCornell();
    const Image bounce = PhotonPointsDrawer().renderAov(
        *f.runner, {.points = PhotonPoints::Bounce, .colour = PhotonColour::Power}, false);
    const PointsMean red = averagePoints(bounce, kRedWall);
    const PointsMean green = averagePoints(bounce, kGreenWall);
    ASSERT_GE(red.points, kMinPoints);
    ASSERT_GE(green.points, kMinPoints);
    // In linear power (the walls' albedos differ 3x and more between these channels; gamma
    // squeezes the ratio).
    const auto decode = [](double c) { return std::pow(c, double(kGamma)); };
    EXPECT_GT(decode(red.colour.x), 2.0 * decode(red.colour.y))
        << "photons leaving the red wall are red";
    EXPECT_GT(decode(green.colour.y), 2.0 * decode(green.colour.x))
        << "photons leaving the green wall are green";
    // Russian roulette divides a survivor's power by its survival probability, so bounce photons
    // off the white floor carry about the mean emitted power: kPhotonPowerWhite of it is white,
    // so they show near 1 / kPhotonPowerWhite (decoded). A scale off by a light's photon count
    // or a unit would miss by orders of magnitude; 0.5x..1.6x covers the floor's albedo (0.76)
    // and the spread of importance-sampled powers.
    const PointsMean floor = averagePoints(bounce, kFloor);
    ASSERT_GE(floor.points, kMinPoints);
    const double decoded = decode(floor.colour.y) * kPhotonPowerWhite;
    EXPECT_GT(decoded, 0.5);
    EXPECT_LT(decoded, 1.6);
}

TEST_F(PhotonPointsTest, AovNamesParse) {
    const auto aov = findPhotonAov("bounce_power");
    ASSERT_TRUE(aov.has_value());
    EXPECT_EQ(aov->points, PhotonPoints::Bounce);
    EXPECT_EQ(aov->colour, PhotonColour::Power);
    EXPECT_TRUE(findPhotonAov("result_direction").has_value());
    EXPECT_FALSE(findPhotonAov("result").has_value());
    EXPECT_FALSE(findPhotonAov("both_power").has_value());
    EXPECT_FALSE(findPhotonAov("result_kind").has_value());
}

} // namespace
} // namespace ispm::test
