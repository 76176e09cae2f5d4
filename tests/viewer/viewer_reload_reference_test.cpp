// `ispm view` F5 and reference views on a virtual display: a broken shader keeps the old program
// and reports the error while rendering goes on, the fixed one is used; a reference (loaded or
// path-traced inside the viewer) gives the side-by-side, heat map and relMSE/SSIM views.
#include "image/image_io.h"
#include "image/metrics.h"
#include "render/shader_root.h"
#include "support/run_ispm.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

namespace ispm::test {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 64; // render region: small, the path tracer runs on a software renderer
const std::string kCornell = std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json";
// One code value of an 8-bit screenshot: the same frame read twice differs by rounding only.
constexpr double kCodeValue = 1.0 / 255.0;

std::string sizeArgs() {
    return " --width " + std::to_string(kSize) + " --height " + std::to_string(kSize);
}

// Mean over the scene region [x0, x1) x [0, kSize) of the three channels.
double computeRegionMean(const Image& image, int x0, int x1) {
    double sum = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = x0; x < x1; ++x)
            sum += static_cast<double>(image.at(x, y).r + image.at(x, y).g + image.at(x, y).b);
    }
    return sum / (3.0 * (x1 - x0) * kSize);
}

double computeRegionFraction(const Image& image, int rows,
                             const std::function<bool(const glm::vec3&)>& test) {
    int hits = 0;
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < kSize; ++x)
            hits += test(image.at(x, y)) ? 1 : 0;
    }
    return static_cast<double>(hits) / (rows * kSize);
}

// Every "reference: relMSE R  SSIM S" line the viewer printed, in order.
std::vector<std::pair<double, double>> parseMetrics(const std::string& output) {
    std::vector<std::pair<double, double>> metrics;
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
        double relMse = 0.0;
        double ssim = 0.0;
        if (std::sscanf(line.c_str(), "reference: relMSE %lf SSIM %lf", &relMse, &ssim) == 2) {
            metrics.emplace_back(relMse, ssim);
        }
    }
    return metrics;
}

void replaceOnce(const fs::path& file, const std::string& from, const std::string& to) {
    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    std::string s = text.str();
    const size_t at = s.find(from);
    ASSERT_NE(at, std::string::npos) << file << " no longer contains: " << from;
    s.replace(at, from.size(), to);
    std::ofstream(file) << s;
}

class ViewerReloadReferenceTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() /
               ("ispm_viewer_reload_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        fs::create_directories(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    std::string writeScript(const std::string& text) const {
        std::ofstream(path("input.txt")) << text;
        return path("input.txt");
    }
    fs::path mDir;
};

// Waits for `file` (written by the viewer) unless `stop` is set; false on timeout.
bool waitForFile(const fs::path& file, const std::atomic<bool>& stop) {
    constexpr auto kTimeout = std::chrono::seconds(30);
    constexpr auto kPoll = std::chrono::milliseconds(10);
    const auto start = std::chrono::steady_clock::now();
    while (!fs::exists(file)) {
        if (stop || std::chrono::steady_clock::now() - start > kTimeout) return false;
        std::this_thread::sleep_for(kPoll);
    }
    return true;
}

TEST_F(ViewerReloadReferenceTest, ReloadKeepsTheOldProgramOnErrorAndUsesTheFixedOne) {
    const fs::path shaders = mDir / "shaders";
    fs::copy(getShaderRoot(), shaders, fs::copy_options::recursive);
    const fs::path tonemap = shaders / "tonemap" / "tonemap.frag";
    // The viewer writes a.png, waits for "broken", reloads and writes b.png, waits for "fixed",
    // reloads and writes c.png; the test edits the shader in between from another thread.
    const std::string script = writeScript(
        "frames 1\nwrite_aov display " + path("a.png") + "\nwait_file " + path("broken") +
        "\nreload_shaders\nframes 1\nwrite_aov display " + path("b.png") + "\nwait_file " +
        path("fixed") + "\nreload_shaders\nframes 1\nwrite_aov display " + path("c.png") + "\n");
    std::atomic<bool> stop = false;
    std::thread editor([&] {
        if (!waitForFile(path("a.png"), stop)) return;
        replaceOnce(tonemap, "void main() {", "void main() {\n    this is not glsl;");
        std::ofstream(path("broken")) << "";
        if (!waitForFile(path("b.png"), stop)) return;
        // Fixed, and visibly different: display values at half.
        replaceOnce(tonemap, "    this is not glsl;\n", "");
        replaceOnce(tonemap, "outColor = vec4(pow(display", "outColor = vec4(0.5 * pow(display");
        std::ofstream(path("fixed")) << "";
    });
    const RunResult r = runIspm("view " + kCornell + sizeArgs() + " --frames 10 --script " + script,
                                Stderr::Merge, "ISPM_SHADER_DIR=" + shaders.string());
    stop = true;
    editor.join();
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("OpenGL errors"), std::string::npos) << r.output;
    // The failure is reported with the file and line, and only the edited program was rebuilt.
    EXPECT_NE(r.output.find("1 failed (old kept)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("tonemap/tonemap.frag:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("shaders: rebuilt 1 of"), std::string::npos) << r.output;

    const Image a = readImage(path("a.png"));
    const double before = computeRegionMean(a, 0, kSize);
    // The broken shader left the old program running: the same image.
    EXPECT_NEAR(computeRegionMean(readImage(path("b.png")), 0, kSize), before, kCodeValue);
    // The fixed one halves the display values (rounding: a code value either way).
    EXPECT_NEAR(computeRegionMean(readImage(path("c.png")), 0, kSize), 0.5 * before,
                2 * kCodeValue);
}

TEST_F(ViewerReloadReferenceTest, ReferenceViewsCompareWithTheTotal) {
    // The reference is the same render (relMSE ~0), then twice as bright (relative error 1/2).
    ASSERT_EQ(runIspm("render " + kCornell + sizeArgs() + " -q --aov total -o " + path("same.pfm"))
                  .exitCode,
              0);
    Image bright = readImage(path("same.pfm"));
    for (glm::vec3& p : bright.pixels)
        p *= 2.0f;
    writeImage(path("bright.pfm"), bright);
    const std::string script = writeScript(
        "press f2\nview error heat map\nframes 1\ncompute_metrics\nscreenshot " +
        path("heat_same.png") + "\nload_reference " + path("bright.pfm") +
        "\ncompute_metrics\nscreenshot " + path("heat_bright.png") +
        "\nview side by side\nscreenshot " + path("split.png") + "\nview total\nscreenshot " +
        path("total.png") +
        "\nrender_reference on\nview reference\nframes 4\ncompute_metrics\nscreenshot " +
        path("traced.png") + "\n");
    const RunResult r = runIspm("view " + kCornell + sizeArgs() + " --reference " +
                                path("same.pfm") + " --frames 14 --script " + script);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("OpenGL errors"), std::string::npos) << r.output;
    const auto metrics = parseMetrics(r.output);
    ASSERT_EQ(metrics.size(), 3u) << r.output;
    // The same render: only float summation order differs (see ViewerWindowTest).
    constexpr double kSameRelMse = 1e-6;
    EXPECT_LT(metrics[0].first, kSameRelMse);
    EXPECT_GT(metrics[0].second, 0.999);
    // Twice as bright: what metrics.h says for the rendered total against it (the view's total
    // is that render up to summation order).
    const Image same = readImage(path("same.pfm"));
    constexpr double kMetricsTolerance = 1e-4;
    EXPECT_NEAR(metrics[1].first, computeRelMse(same, bright), kMetricsTolerance);
    EXPECT_NEAR(metrics[1].second, computeSsim(same, bright), kMetricsTolerance);
    // The path tracer ran inside the viewer and gave a finite comparison.
    EXPECT_NE(r.output.find(" spp)"), std::string::npos) << r.output;
    EXPECT_TRUE(std::isfinite(metrics[2].first));

    // Heat map above the legend rows: no error is the scale's dark blue, an error of 1/2 (the
    // middle of the default 0..1 range) its green.
    constexpr int kRowsAboveLegend = kSize - 16;
    const auto isBlue = [](const glm::vec3& c) { return c.b > 0.4f && c.r < 0.1f && c.g < 0.1f; };
    const auto isGreen = [](const glm::vec3& c) { return c.g > 0.6f && c.r < 0.3f && c.g > c.b; };
    constexpr double kMostPixels = 0.9;
    EXPECT_GT(computeRegionFraction(readImage(path("heat_same.png")), kRowsAboveLegend, isBlue),
              kMostPixels);
    EXPECT_GT(computeRegionFraction(readImage(path("heat_bright.png")), kRowsAboveLegend, isGreen),
              kMostPixels);

    // Side by side: the left half is the total as the total view shows it, the right half the
    // twice-as-bright reference at the same exposure (2^(1/2.2) = 1.37 brighter once encoded).
    const Image split = readImage(path("split.png"));
    const Image total = readImage(path("total.png"));
    constexpr int kQuarter = kSize / 4;
    EXPECT_NEAR(computeRegionMean(split, 0, kQuarter), computeRegionMean(total, 0, kQuarter),
                kCodeValue);
    EXPECT_GT(computeRegionMean(split, 3 * kQuarter, kSize),
              1.2 * computeRegionMean(total, 3 * kQuarter, kSize));
    // The traced reference shows the lit box, not the black of "no reference yet".
    constexpr double kLitMean = 0.05;
    EXPECT_GT(computeRegionMean(readImage(path("traced.png")), 0, kSize), kLitMean);
}

} // namespace
} // namespace ispm::test
