// `ispm view` on a virtual display (ctest runs this binary under xvfb-run): the window shows the
// scene and the panels, scripted input moves the camera and changes settings, and a setting
// changed through the viewer renders exactly as the same `ispm render --set` does.
#include "image/image_io.h"
#include "image/metrics.h"
#include "scene/scene_loader.h"
#include "support/run_ispm.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

namespace ispm::test {
namespace {

constexpr int kSize = 128; // render region; the panel column is added to the window's width
const std::string kCornell = std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json";

// Fraction of pixels in columns [x0, x1) that satisfy `test`.
double computeFraction(const Image& image, int x0, int x1,
                       const std::function<bool(const glm::vec3&)>& test) {
    int hits = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = x0; x < x1; ++x)
            hits += test(image.at(x, y)) ? 1 : 0;
    }
    return static_cast<double>(hits) / static_cast<double>((x1 - x0) * image.height);
}

// The walls' display colours, e.g. red (0.5, 0.18, 0.15) and green (0.27, 0.44, 0.2): one channel
// clearly above both others, and not black.
constexpr float kDominance = 1.4f;
constexpr float kMinChannel = 0.1f;
bool isRed(const glm::vec3& c) {
    return c.r > kMinChannel && c.r > kDominance * glm::max(c.g, c.b);
}
bool isGreen(const glm::vec3& c) {
    return c.g > kMinChannel && c.g > kDominance * glm::max(c.r, c.b);
}

double computeMean(const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels)
        sum += static_cast<double>(p.r + p.g + p.b);
    return sum / (3.0 * static_cast<double>(image.getPixelCount()));
}

// Fraction of the scene region's pixels whose colour moved by more than a tenth of the range:
// far above the frame-to-frame noise of a still camera (none: the seed is fixed).
double computeChangedFraction(const Image& a, const Image& b) {
    constexpr float kChange = 0.1f;
    int changed = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec3 d = glm::abs(a.at(x, y) - b.at(x, y));
            changed += glm::max(d.r, glm::max(d.g, d.b)) > kChange ? 1 : 0;
        }
    }
    return static_cast<double>(changed) / (kSize * kSize);
}

class ViewerWindowTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mDir = std::filesystem::temp_directory_path() /
               ("ispm_viewer_test_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        std::filesystem::create_directories(mDir);
    }
    void TearDown() override { std::filesystem::remove_all(mDir); }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    std::string writeScript(const std::string& text) const {
        std::ofstream(path("input.txt")) << text;
        return path("input.txt");
    }
    static std::string sizeArgs() {
        return " --width " + std::to_string(kSize) + " --height " + std::to_string(kSize);
    }
    void expectClean(const RunResult& r, const std::string& what) const {
        ASSERT_EQ(r.exitCode, 0) << what << "\n" << r.output;
        EXPECT_EQ(r.output.find("OpenGL errors"), std::string::npos) << r.output;
    }
    std::filesystem::path mDir;
};

TEST_F(ViewerWindowTest, ScreenshotShowsSceneAndPanels) {
    // F2 hides the frame-rate overlay: the scene region is then the frame alone.
    const RunResult view =
        runIspm("view " + kCornell + sizeArgs() + " --script " + writeScript("press f2\n") +
                " --frames 30 --screenshot " + path("ui.png"));
    expectClean(view, "view");
    const RunResult render =
        runIspm("render " + kCornell + sizeArgs() + " -q -o " + path("scene.png"));
    expectClean(render, "render");
    const Image ui = readImage(path("ui.png"));
    const Image scene = readImage(path("scene.png"));
    ASSERT_EQ(ui.height, kSize);
    ASSERT_GT(ui.width, 2 * kSize); // the panel column is wider than the scene here

    // The scene region is the display AOV as `render` writes it: the same frame through 8-bit
    // values on both sides, so one code value of difference covers rounding.
    const double kMaxMeanDifference = 1.0 / 255.0;
    double difference = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec3 d = glm::abs(ui.at(x, y) - scene.at(x, y));
            difference += static_cast<double>(d.r + d.g + d.b) / 3.0;
        }
    }
    EXPECT_LT(difference / (kSize * kSize), kMaxMeanDifference);
    // The red wall fills the left edge of the Cornell box, the green wall the right edge.
    const double kMinWallFraction = 0.05;
    EXPECT_GT(computeFraction(ui, 0, kSize / 4, isRed), kMinWallFraction);
    EXPECT_GT(computeFraction(ui, 3 * kSize / 4, kSize, isGreen), kMinWallFraction);

    // The panel column: ImGui's dark grey background (not the black clear colour, not the scene's
    // walls) with light text on it.
    const int x0 = kSize + 1;
    const double black = computeFraction(ui, x0, ui.width, [](const glm::vec3& c) {
        return glm::all(glm::lessThan(c, glm::vec3(0.01f)));
    });
    const double text = computeFraction(ui, x0, ui.width, [](const glm::vec3& c) {
        return glm::all(glm::greaterThan(c, glm::vec3(0.7f)));
    });
    EXPECT_LT(black, 0.05);
    EXPECT_GT(text, 0.01);
    EXPECT_LT(computeFraction(ui, x0, ui.width, isRed), 0.01);
}

TEST_F(ViewerWindowTest, ScriptedInputMovesTheCameraAndChangesSettings) {
    const std::string script = writeScript("frames 2\n"
                                           "write_aov display " +
                                           path("a.png") +
                                           "\n"
                                           "write_aov indirect " +
                                           path("a.pfm") +
                                           "\n"
                                           "key W 20\n"        // fly in ...
                                           "mouse_drag 80 0\n" // ... and turn right
                                           "write_aov display " +
                                           path("b.png") +
                                           "\n"
                                           "set bounces=0\n"
                                           "write_aov indirect " +
                                           path("c.pfm") + "\n");
    expectClean(runIspm("view " + kCornell + sizeArgs() + " --frames 30 --script " + script),
                "view");
    const Image before = readImage(path("a.png"));
    const Image moved = readImage(path("b.png"));
    // Turning right takes the red (left) wall out of view and brings more of the green (right)
    // one in (by ~15%: flying in also darkens the green wall's upper part in the image).
    const double greenBefore = computeFraction(before, 0, kSize, isGreen);
    const double greenAfter = computeFraction(moved, 0, kSize, isGreen);
    const double redBefore = computeFraction(before, 0, kSize, isRed);
    const double redAfter = computeFraction(moved, 0, kSize, isRed);
    EXPECT_GT(greenAfter, greenBefore) << greenBefore << " -> " << greenAfter;
    EXPECT_LT(redAfter, redBefore * 0.5) << redBefore << " -> " << redAfter;
    // bounces = 0 leaves direct light only: the indirect AOV goes from lit to black.
    EXPECT_GT(computeMean(readImage(path("a.pfm"))), 1e-3);
    EXPECT_EQ(computeMean(readImage(path("c.pfm"))), 0.0);
}

TEST_F(ViewerWindowTest, ScriptedSettingRendersAsRenderSet) {
    const std::string script = writeScript("set photons=20000\nset bounces=2\nframes 1\n"
                                           "write_aov total " +
                                           path("view.pfm") +
                                           "\n"
                                           "save_settings " +
                                           path("saved.json") + "\n");
    expectClean(runIspm("view " + kCornell + sizeArgs() + " --frames 3 --script " + script),
                "view");
    const std::string renderArgs = "render " + kCornell + sizeArgs() + " -q --aov total";
    expectClean(runIspm(renderArgs + " --set photons=20000 --set bounces=2 -o " + path("set.pfm")),
                "render --set");
    expectClean(runIspm(renderArgs + " -o " + path("defaults.pfm")), "render");
    const Image view = readImage(path("view.pfm"));
    // Same settings, same seed, same photons: only the order of the float additions in the
    // splat blending and the atomics may differ (observed relMSE ~1e-15). Another seed alone
    // gives relMSE ~4e-2, so 1e-6 separates "the same render" from "another sample" by far.
    constexpr double kSameRenderRelMse = 1e-6;
    EXPECT_LT(computeMetrics(view, readImage(path("set.pfm"))).relMse, kSameRenderRelMse);
    // ... and the change mattered: the defaults (50000 photons, 3 bounces) render otherwise.
    EXPECT_GT(computeMetrics(view, readImage(path("defaults.pfm"))).relMse,
              100 * kSameRenderRelMse);
    // "save" writes what was set as a render block (width/height follow the window, so they
    // are there too), which the scene loader reads back.
    const nlohmann::json saved = nlohmann::json::parse(std::ifstream(path("saved.json")));
    EXPECT_EQ(saved.at("render").at("photons"), 20000);
    EXPECT_EQ(saved.at("render").at("bounces"), 2);
    EXPECT_EQ(saved.at("render").at("width"), kSize);
    nlohmann::json scene = nlohmann::json::parse(std::ifstream(kCornell));
    scene["render"] = saved.at("render");
    std::ofstream(path("resaved.json")) << scene.dump();
    const Scene reloaded = loadScene(path("resaved.json"));
    EXPECT_EQ(reloaded.settings.getInt("photons"), 20000);
    EXPECT_EQ(reloaded.settings.getInt("bounces"), 2);
}

TEST_F(ViewerWindowTest, DebugViewsAndPhotonPointsChangeTheSceneRegion) {
    const std::string script = writeScript("press f2\nframes 1\n"
                                           "screenshot " +
                                           path("display.png") +
                                           "\n"
                                           "points result\n"
                                           "screenshot " +
                                           path("points.png") +
                                           "\n"
                                           "points result direction\n"
                                           "screenshot " +
                                           path("directions.png") +
                                           "\n"
                                           "points none\n"
                                           "view gbuffer normal\n"
                                           "screenshot " +
                                           path("normal.png") + "\n");
    expectClean(runIspm("view " + kCornell + sizeArgs() + " --frames 7 --script " + script),
                "view");
    const Image display = readImage(path("display.png"));
    // Points cover a good part of the box (20k+ result photons over 128 x 128 pixels) ...
    const double kMinPointsChanged = 0.1;
    const Image points = readImage(path("points.png"));
    EXPECT_GT(computeChangedFraction(display, points), kMinPointsChanged);
    // ... and coloured by direction they change colour (the same points, other colours).
    EXPECT_GT(computeChangedFraction(points, readImage(path("directions.png"))), kMinPointsChanged);
    // ... and the normal view recolours nearly every pixel.
    const double kMinViewChanged = 0.5;
    EXPECT_GT(computeChangedFraction(display, readImage(path("normal.png"))), kMinViewChanged);
}

TEST_F(ViewerWindowTest, LightImportanceViewShowsWhereThePhotonsGo) {
    // From inside the courtyard's room, the sun's map is bright where the door lets its light
    // in and dim elsewhere (the floor that keeps every texel a share).
    const std::string courtyard = std::string(ISPM_ASSET_DIR) + "/scenes/courtyard.json";
    const std::string script = writeScript(
        "press f2\nframes 1\nview light importance\nscreenshot " + path("importance.png") + "\n");
    expectClean(runIspm("view " + courtyard + " --camera room" + sizeArgs() +
                        " --set photons=10000 --set shadow_map_size=256 --frames 5 --script " +
                        script),
                "view");
    const Image map = readImage(path("importance.png"));
    const double bright =
        computeFraction(map, 0, kSize, [](const glm::vec3& c) { return c.r > 0.9f; });
    const double dim = computeFraction(
        map, 0, kSize, [](const glm::vec3& c) { return c.r > 0.05f && c.r < 0.5f; });
    std::printf("light importance view: %.4f white, %.4f dim\n", bright, dim);
    // Measured: 1.7% of the map white (20x the uniform share or more), 97% dim.
    EXPECT_GT(bright, 0.001);
    EXPECT_LT(bright, 0.2);
    EXPECT_GT(dim, 0.5);
}

TEST_F(ViewerWindowTest, BadScriptIsBadInput) {
    const std::string script = writeScript("frames 1\nkey Z 3\n");
    const RunResult r = runIspm("view " + kCornell + " --frames 1 --script " + script);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("input.txt:2"), std::string::npos) << r.output;
}

} // namespace
} // namespace ispm::test
