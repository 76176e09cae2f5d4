// Post-processing (MotionBlurPass, DepthBlurPass, BloomPass between compose and tone map): each
// off leaves every image bit-identical and runs no pass; each on keeps the image's energy (sum
// of radiance) and moves light only where it should: bloom around a bright square and no farther
// than its kernel, depth blur across an out-of-focus square's edge by its circle of confusion
// while an in-focus square stays sharp, motion blur along the motion only.
#include "support/gl_fixture.h"

#include "render/frame.h"
#include "render/readback.h"
#include "scene/mesh_builder.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace ispm::test {
namespace {

constexpr int kSize = 64;                 // px
constexpr float kFovYDeg = 45.0f;         // the default camera's
constexpr float kEmission = 100.0f;       // W/(m^2 sr): the squares' radiance
constexpr double kEnergyTolerance = 0.01; // the bound; measured ratios are 1 +- 1e-6

// Pixels per radian at the image centre: H / (2 tan(fovY / 2)).
double getPixelsPerRadian() {
    return kSize / (2.0 * std::tan(0.5 * glm::radians(double(kFovYDeg))));
}

// Emissive squares facing a camera at the origin that looks down -z; nothing else (black
// background, no lights): the composed image is the squares' emission, exactly.
struct Square {
    glm::vec3 centre;
    float halfSizeM;
};

Scene makeSquares(const std::vector<Square>& squares) {
    Scene scene;
    scene.sourcePath = "post test squares";
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fovYDeg = kFovYDeg;
    Material m;
    m.name = "emitter";
    m.emission = glm::vec3(kEmission);
    scene.materials.push_back(m);
    for (const Square& s : squares) {
        Mesh mesh;
        mesh.name = "square";
        const float h = s.halfSizeM;
        appendQuad(mesh, {-h, -h, 0.0f}, {h, -h, 0.0f}, {h, h, 0.0f}, {-h, h, 0.0f}, 0);
        scene.instances.push_back(
            {uint32_t(scene.meshes.size()), glm::translate(glm::mat4(1.0f), s.centre)});
        scene.meshes.push_back(mesh);
    }
    return scene;
}

Settings makeSettings() {
    Settings s = makeTestSettings({{"width", kSize},
                                   {"height", kSize},
                                   {"photons", 0},
                                   {"bounces", 0},
                                   {"shadow_map_size", 64}});
    return s;
}

Image render(const Scene& scene, const Settings& settings) {
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    return readTextureImage(runner.getAov(Aov::Total));
}

double computeSum(const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels)
        sum += double(p.r) + double(p.g) + double(p.b);
    return sum;
}

double computeEnergyRatio(const Image& after, const Image& before) {
    const double ratio = computeSum(after) / computeSum(before);
    std::printf("energy after / before: %.7f\n", ratio);
    return ratio;
}

// Euclidean distance in pixels from each pixel to the nearest lit pixel of `image` (0 on one).
std::vector<double> computeDistanceToLit(const Image& image) {
    std::vector<double> distance(image.pixels.size(), std::numeric_limits<double>::infinity());
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            double& d = distance[size_t(y * image.width + x)];
            for (int v = 0; v < image.height; ++v) {
                for (int u = 0; u < image.width; ++u) {
                    if (image.at(u, v).r > 0.0f) d = std::min(d, std::hypot(u - x, v - y));
                }
            }
        }
    }
    return distance;
}

class PostTest : public GlTest {};

size_t countDifferingPixels(const Image& a, const Image& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
        differing += a.pixels[i] != b.pixels[i] ? 1u : 0u;
    return differing;
}

Settings makeCornellSettings(const Scene& cornell, int bounces) {
    Settings s = withSettings(cornell.settings, {{"width", 48},
                                                 {"height", 48},
                                                 {"photons", 4000},
                                                 {"bounces", bounces},
                                                 {"shadow_map_size", 256}});
    return s;
}

// Each effect set to its off value, the others' parameters moved away from their defaults.
Settings setEffectsOff(Settings s) {
    s = withSettings(s, {{"motion_blur_shutter", 0},
                         {"dof_aperture_m", 0},
                         {"dof_focus_m", 3},
                         {"bloom_intensity", 0},
                         {"bloom_threshold", 0.01},
                         {"bloom_radius_px", 5}});
    return s;
}

TEST_F(PostTest, OffIsBitIdenticalAndRunsNoPass) {
    const Scene cornell = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    // Direct light and emission only: deterministic, so two runners compare bit for bit (the
    // photon passes' atomics add in a different order from run to run).
    const Settings defaults = makeCornellSettings(cornell, 0);
    FrameRunner a(cornell, defaults, gl::TimingMethod::CpuFinish);
    FrameRunner b(cornell, setEffectsOff(defaults), gl::TimingMethod::CpuFinish);
    for (int frame = 0; frame < 2; ++frame) {
        a.renderFrame();
        b.renderFrame();
    }
    for (Aov aov : {Aov::Total, Aov::Display, Aov::Direct, Aov::Indirect}) {
        EXPECT_EQ(
            countDifferingPixels(readTextureImage(a.getAov(aov)), readTextureImage(b.getAov(aov))),
            0u)
            << "AOV " << int(aov);
    }
    b.waitForTimings();
    ASSERT_FALSE(b.getTimings().passes.empty());
    for (const PassTiming& t : b.getTimings().passes) {
        EXPECT_NE(t.name, "motion_blur");
        EXPECT_NE(t.name, "depth_blur");
        EXPECT_NE(t.name, "bloom");
    }
    // With indirect light, within one frame: the total is compose's sum itself, direct +
    // indirect + emission (Cornell's background is never seen), to the bit.
    FrameRunner c(cornell, setEffectsOff(makeCornellSettings(cornell, 2)),
                  gl::TimingMethod::CpuFinish);
    c.renderFrame();
    const Image direct = readTextureImage(c.getAov(Aov::Direct));
    const Image indirect = readTextureImage(c.getAov(Aov::Indirect));
    const Image emission =
        readTextureImage(c.getPasses().gbuffer.getGBuffer().getChannel("emission"));
    Image composed(direct.width, direct.height);
    for (size_t i = 0; i < composed.pixels.size(); ++i)
        composed.pixels[i] = (direct.pixels[i] + indirect.pixels[i]) + emission.pixels[i];
    EXPECT_EQ(countDifferingPixels(readTextureImage(c.getAov(Aov::Total)), composed), 0u);
}

TEST_F(PostTest, EachOnChangesTheTotalOnlyAndIsTimed) {
    const Scene scene = makeSquares({{{0.0f, 0.0f, -2.0f}, 0.2f}, {{0.6f, 0.4f, -5.0f}, 0.3f}});
    const Settings base = makeSettings();
    FrameRunner plain(scene, base, gl::TimingMethod::CpuFinish);
    plain.renderFrame();
    const Image total = readTextureImage(plain.getAov(Aov::Total));
    const Image direct = readTextureImage(plain.getAov(Aov::Direct));
    const struct {
        const char* setting;
        double value;
        const char* pass;
    } effects[] = {{"motion_blur_shutter", 1.0, "motion_blur"},
                   {"dof_aperture_m", 0.3, "depth_blur"},
                   {"bloom_intensity", 0.5, "bloom"}};
    for (const auto& e : effects) {
        Settings s = base;
        s.set(e.setting, e.value, "test");
        FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
        runner.renderFrame();
        runner.waitForTimings();
        const auto& timings = runner.getTimings().passes;
        EXPECT_TRUE(std::any_of(timings.begin(), timings.end(), [&](const PassTiming& t) {
            return t.name == e.pass;
        })) << e.pass;
        // The lights stay as composed; only the total (and what the tone map shows) moves.
        const Image d = readTextureImage(runner.getAov(Aov::Direct));
        EXPECT_EQ(d.pixels, direct.pixels) << e.setting;
        const Image t = readTextureImage(runner.getAov(Aov::Total));
        EXPECT_NEAR(computeEnergyRatio(t, total), 1.0, kEnergyTolerance) << e.setting;
    }
}

TEST_F(PostTest, AllOnKeepTheCornellBoxEnergyAsTheCameraTurns) {
    Scene cornell = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    Settings s = makeCornellSettings(cornell, 0); // direct light: the same in both runners
    s = withSettings(s, {{"width", kSize}, {"height", kSize}});
    Settings post = withSettings(s, {{"motion_blur_shutter", 1.0},
                                     {"dof_aperture_m", 0.05},
                                     {"bloom_intensity", 0.3},
                                     {"bloom_threshold", 0.05}});
    FrameRunner blurred(cornell, post, gl::TimingMethod::CpuFinish);
    blurred.renderFrame();
    // The camera turns by about 4 px between the frames.
    cornell.camera.target +=
        glm::vec3(0.04f, 0.0f, 0.0f) * glm::length(cornell.camera.target - cornell.camera.position);
    blurred.renderFrame();
    const Image after = readTextureImage(blurred.getAov(Aov::Total));
    const Image before = render(cornell, s);
    EXPECT_NEAR(computeEnergyRatio(after, before), 1.0, kEnergyTolerance);
    EXPECT_GT(countDifferingPixels(after, before), after.pixels.size() / 2);
}

TEST_F(PostTest, BloomSpreadsTheBrightPartWithinItsRadiusAndKeepsEnergy) {
    // A bright square (radiance 100, 15 px wide) on black.
    const Scene scene = makeSquares({{{0.0f, 0.0f, -2.0f}, 0.1f}});
    const Image before = render(scene, makeSettings());
    constexpr float kRadiusPx = 8.0f;
    Settings s = withSettings(
        makeSettings(),
        {{"bloom_intensity", 0.5}, {"bloom_threshold", 1.0}, {"bloom_radius_px", kRadiusPx}});
    const Image after = render(scene, s);
    EXPECT_NEAR(computeEnergyRatio(after, before), 1.0, kEnergyTolerance);
    const std::vector<double> distance = computeDistanceToLit(before);
    double ring = 0.0;   // light 1..4 px outside the square, black before
    double beyond = 0.0; // light farther than the separable kernel reaches (sqrt(2) r)
    for (size_t i = 0; i < after.pixels.size(); ++i) {
        const double v = after.pixels[i].r;
        if (distance[i] >= 1.0 && distance[i] <= 4.0) {
            ring += v;
            EXPECT_GT(v, 0.0f) << "pixel " << i;
        }
        if (distance[i] > std::sqrt(2.0) * double(kRadiusPx) + 1.0) beyond += v;
    }
    std::printf("bloom: ring 1-4 px holds %.4f of the energy\n", ring / computeSum(after) * 3.0);
    EXPECT_GT(ring, 0.0);
    EXPECT_EQ(beyond, 0.0);
    // The light came out of the square: its centre darker by up to intensity x the share above
    // the threshold (less what its own blur gives back).
    const glm::vec3 centre = after.at(kSize / 2, kSize / 2);
    EXPECT_LT(centre.r, 0.95f * kEmission);
    EXPECT_GT(centre.r, 0.5f * kEmission);
    // A threshold above the square's luminance blooms nothing.
    s.set("bloom_threshold", 2.0 * double(kEmission), "test");
    EXPECT_EQ(render(scene, s).pixels, before.pixels);
}

TEST_F(PostTest, DepthBlurWidensAnOutOfFocusEdgeByItsCircleAndKeepsFocusSharp) {
    // Square A at the focus distance, at the image centre; square B farther away, to the right.
    constexpr double kFocusM = 2.0;
    constexpr double kFarM = 6.0;
    constexpr double kApertureM = 0.3;
    const Scene scene =
        makeSquares({{{0.0f, 0.0f, -float(kFocusM)}, 0.2f}, {{1.7f, 0.0f, -float(kFarM)}, 0.3f}});
    const Image before = render(scene, makeSettings());
    Settings s =
        withSettings(makeSettings(), {{"dof_aperture_m", kApertureM}, {"dof_focus_m", kFocusM}});
    const Image after = render(scene, s);
    EXPECT_NEAR(computeEnergyRatio(after, before), 1.0, kEnergyTolerance);
    // The thin lens's circle at B's depth (shared/post_data.h), computed here from the optics:
    // diameter A |1/d - 1/S| in radians.
    const double radiusPx =
        0.5 * kApertureM * std::abs(1.0 / kFarM - 1.0 / kFocusM) * getPixelsPerRadian();
    const double rimPx = 1.5 + 0.25 * radiusPx; // post_common.glsl's soft rim
    std::printf("depth blur: circle of confusion at %g m: radius %.2f px\n", kFarM, radiusPx);
    const std::vector<double> distance = computeDistanceToLit(before);
    int widened = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const size_t i = size_t(y * kSize + x);
            const float v = after.at(x, y).r;
            if (x < kSize / 2 + 10) {
                // Square A and its surroundings (B's light does not reach them): untouched.
                EXPECT_NEAR(v, before.at(x, y).r, 1e-4f * kEmission) << x << "," << y;
                continue;
            }
            // Around B: lit out to its circle's radius, black beyond radius + rim.
            if (before.at(x, y).r == 0.0f && distance[i] <= radiusPx - 1.0) {
                EXPECT_GT(v, 0.0f) << x << "," << y;
                ++widened;
            }
            if (distance[i] > radiusPx + 0.5 * rimPx + 1.0) {
                EXPECT_EQ(v, 0.0f) << x << "," << y;
            }
        }
    }
    EXPECT_GT(widened, 20);
    // The focus derived from the image centre (square A at 2 m) is the one set by hand.
    Settings automatic = withSettings(makeSettings(), {{"dof_aperture_m", kApertureM}});
    const Image autoFocus = render(scene, automatic);
    for (size_t i = 0; i < after.pixels.size(); ++i)
        EXPECT_NEAR(autoFocus.pixels[i].r, after.pixels[i].r, 1e-5f * kEmission) << i;
}

TEST_F(PostTest, MotionBlurSmearsAlongTheMotionOnlyAndKeepsEnergy) {
    // A square at 2 m moving 0.3 m to the right between two frames (11.6 px).
    constexpr double kDepthM = 2.0;
    constexpr double kMoveM = 0.3;
    Scene scene = makeSquares({{{-0.15f, 0.0f, -float(kDepthM)}, 0.15f}});
    Settings s = withSettings(makeSettings(), {{"motion_blur_shutter", 1.0}});
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    scene.instances[0].worldFromObject =
        glm::translate(glm::mat4(1.0f), glm::vec3(-0.15f + float(kMoveM), 0.0f, -float(kDepthM)));
    runner.updateScene();
    runner.renderFrame();
    const Image after = readTextureImage(runner.getAov(Aov::Total));
    const Image before = render(scene, makeSettings()); // the square where it is now, still
    EXPECT_NEAR(computeEnergyRatio(after, before), 1.0, kEnergyTolerance);
    // The velocity channel: the square's motion in pixels, x right, y up.
    const double expectedPx = kMoveM / kDepthM * getPixelsPerRadian();
    const Image velocity =
        readTextureImage(runner.getPasses().gbuffer.getGBuffer().getChannel("velocity"));
    const glm::vec3 v = velocity.at(kSize / 2 + 2, kSize / 2);
    std::printf("motion blur: velocity %.3f %.3f px (expected %.3f 0)\n", double(v.x), double(v.y),
                expectedPx);
    EXPECT_NEAR(double(v.x), expectedPx, 0.02 * expectedPx);
    EXPECT_NEAR(double(v.y), 0.0, 0.01);
    // Rows the square does not cover stay black; in its rows, light reaches half the streak to
    // either side and no farther.
    int smeared = 0;
    for (int y = 0; y < kSize; ++y) {
        bool rowLit = false;
        int first = kSize;
        int last = -1;
        for (int x = 0; x < kSize; ++x) {
            if (before.at(x, y).r > 0.0f) {
                rowLit = true;
                first = std::min(first, x);
                last = std::max(last, x);
            }
        }
        for (int x = 0; x < kSize; ++x) {
            const float value = after.at(x, y).r;
            if (!rowLit) {
                EXPECT_EQ(value, 0.0f) << x << "," << y;
                continue;
            }
            const int away = x < first ? first - x : (x > last ? x - last : 0);
            if (away >= 1 && away <= int(0.5 * expectedPx) - 1) {
                EXPECT_GT(value, 0.0f) << x << "," << y;
                ++smeared;
            }
            if (away > int(0.5 * expectedPx) + 2) {
                EXPECT_EQ(value, 0.0f) << x << "," << y;
            }
        }
    }
    EXPECT_GT(smeared, 20);
    // A still frame does not blur: the image is the composed one.
    runner.renderFrame();
    EXPECT_EQ(readTextureImage(runner.getAov(Aov::Total)).pixels, before.pixels);
}

TEST_F(PostTest, VelocityIsDrawnOnlyForItsReaders) {
    // The square of the motion-blur test moves 0.3 m (11.6 px) between two frames.
    Scene scene = makeSquares({{{-0.15f, 0.0f, -2.0f}, 0.15f}});
    FrameRunner runner(scene, makeSettings(), gl::TimingMethod::CpuFinish);
    const auto moveAndMeasure = [&](float xM) {
        scene.instances[0].worldFromObject =
            glm::translate(glm::mat4(1.0f), glm::vec3(xM, 0.0f, -2.0f));
        runner.updateScene();
        runner.renderFrame();
        const Image velocity =
            readTextureImage(runner.getPasses().gbuffer.getGBuffer().getChannel("velocity"));
        float largest = 0.0f;
        for (const glm::vec3& v : velocity.pixels)
            largest = std::max(largest, v.x);
        return largest;
    };
    runner.renderFrame();
    // Motion blur off, nothing showing the channel: it is left out and reads zero.
    EXPECT_EQ(moveAndMeasure(0.15f), 0.0f);
    // Kept (the viewer's debug view), the same motion is there: 11.6 px to the right.
    runner.setPresentation({.keepVelocity = true});
    EXPECT_GT(moveAndMeasure(0.45f), 10.0f);
    runner.setPresentation({.keepVelocity = false});
    EXPECT_EQ(moveAndMeasure(0.75f), 0.0f); // cleared when it leaves
}

TEST_F(PostTest, AStillViewHasNoVelocityWhileAccumulating) {
    // Accumulated frames look through new sub-pixel offsets: the velocity channel leaves them out.
    const Scene scene = makeSquares({{{0.0f, 0.0f, -2.0f}, 0.5f}});
    Settings s = withSettings(makeSettings(), {{"accumulate", 4}});
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    runner.setPresentation(
        {.keepVelocity = true}); // drawn without motion blur (else it holds zero anyway)
    for (int frame = 0; frame < 3; ++frame) {
        runner.renderFrame();
        const Image velocity =
            readTextureImage(runner.getPasses().gbuffer.getGBuffer().getChannel("velocity"));
        float largest = 0.0f;
        for (const glm::vec3& v : velocity.pixels)
            largest = std::max({largest, std::abs(v.x), std::abs(v.y)});
        EXPECT_LT(largest, 1e-3f) << "frame " << frame;
    }
}

} // namespace
} // namespace ispm::test
