// `ispm bench` contract: the table and the JSON report the same passes, --json is one JSON object
// on stdout, and bad counts exit 2. Tiny images and few frames: these check the report, not speed.
#include "support/run_ispm.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace ispm::test {
namespace {

RunResult run(const std::string& args, bool mergeStderr) {
    return runIspm(args, mergeStderr ? Stderr::Merge : Stderr::Discard);
}

constexpr const char* kTinyScene = R"({
  "camera": {"position": [0, 1, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 50},
  "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
  "objects": [{"type": "box", "min": [-1, -0.1, -1], "max": [1, 0, 1], "material": "grey"}],
  "lights": [{"type": "point", "position": [0, 1, 0], "intensity": [2, 2, 2]}]
})";

// Small enough that a whole run is mostly context creation and shader builds; the light cameras'
// default 1024^2 G-buffers would otherwise dominate every frame on llvmpipe.
constexpr const char* kSmallRun =
    " --width 32 --height 32 --frames 2 --warmup 1 --set shadow_map_size=64";

class BenchTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mDir = std::filesystem::temp_directory_path() /
               ("ispm_bench_test_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        std::filesystem::create_directories(mDir);
        mScene = (mDir / "tiny.json").string();
        std::ofstream(mScene) << kTinyScene;
    }
    void TearDown() override { std::filesystem::remove_all(mDir); }

    nlohmann::json runJson(const std::string& args) {
        const RunResult r = run("bench " + args + " --json", false);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        // parse() rejects anything after the object: --json prints nothing else on stdout.
        return nlohmann::json::parse(r.output, nullptr, false);
    }

    std::filesystem::path mDir;
    std::string mScene;
};

TEST_F(BenchTest, JsonHasEveryKeyAndConsistentTimes) {
    const nlohmann::json j = runJson(mScene + kSmallRun + " --set seed=3");
    ASSERT_FALSE(j.is_discarded()) << "stdout is not one JSON object";
    for (const char* key :
         {"scene", "width", "height", "frames", "warmup", "renderer", "timing_method", "passes",
          "total_median_ms", "peak_rss_mib", "gl_bytes", "settings"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
    EXPECT_EQ(j["width"], 32);
    EXPECT_EQ(j["height"], 32);
    EXPECT_EQ(j["frames"], 2);
    EXPECT_EQ(j["warmup"], 1);
    EXPECT_EQ(j["settings"]["seed"], 3);
    // Consistent photon counts: every stored photon came from an emitted one (at most `bounces`
    // results each), and nothing overflowed at this size.
    ASSERT_TRUE(j.contains("photons"));
    const auto& photons = j["photons"];
    EXPECT_GT(photons["emitted"].get<int>(), 0);
    EXPECT_LE(photons["bounced"].get<int>(), photons["emitted"].get<int>());
    EXPECT_LE(photons["stored"].get<int>(), 3 * photons["bounced"].get<int>());
    EXPECT_EQ(photons["overflow"].get<int>(), 0);
    // Per light, summing to the totals.
    ASSERT_TRUE(photons.contains("per_light"));
    int emitted = 0;
    int stored = 0;
    for (const auto& light : photons["per_light"]) {
        emitted += light["emitted"].get<int>();
        stored += light["stored"].get<int>();
    }
    EXPECT_EQ(emitted, photons["emitted"].get<int>());
    EXPECT_EQ(stored, photons["stored"].get<int>());
    EXPECT_GT(j["peak_rss_mib"].get<double>(), 0.0);
    EXPECT_GT(j["gl_bytes"].get<double>(), 0.0);
    ASSERT_TRUE(j["passes"].is_array());
    ASSERT_FALSE(j["passes"].empty());
    double largestMedian = 0.0;
    for (const nlohmann::json& p : j["passes"]) {
        EXPECT_FALSE(p["name"].get<std::string>().empty());
        const double median = p["median_ms"].get<double>();
        EXPECT_GE(median, 0.0) << p.dump();
        EXPECT_LE(p["min_ms"].get<double>(), median) << p.dump();
        EXPECT_GE(p["max_ms"].get<double>(), median) << p.dump();
        largestMedian = std::max(largestMedian, median);
    }
    EXPECT_GE(j["total_median_ms"].get<double>(), largestMedian);
}

TEST_F(BenchTest, TextListsThePassesOfTheJsonAndATotal) {
    const nlohmann::json j = runJson(mScene + kSmallRun);
    ASSERT_FALSE(j.is_discarded());
    const RunResult text = run("bench " + mScene + kSmallRun, true);
    ASSERT_EQ(text.exitCode, 0) << text.output;
    for (const nlohmann::json& p : j["passes"]) {
        const std::string name = p["name"].get<std::string>();
        EXPECT_NE(text.output.find("  " + name + " "), std::string::npos)
            << "missing pass '" << name << "' in:\n"
            << text.output;
    }
    EXPECT_NE(text.output.find("  total "), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("32x32"), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("peak RSS"), std::string::npos) << text.output;
}

TEST_F(BenchTest, PresetAppliesOnlyKnownSettings) {
    // The command line wins over the preset's 1280x1024, which keeps this fast.
    const nlohmann::json j = runJson("--preset thesis " + mScene + kSmallRun);
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["width"], 32);
    EXPECT_EQ(j["preset"]["name"], "thesis");
    const nlohmann::json& applied = j["preset"]["applied"];
    const nlohmann::json& skipped = j["preset"]["skipped"];
    EXPECT_NE(std::find(applied.begin(), applied.end(), "width=1280"), applied.end()) << j.dump();
    // The thesis's method: travel radii named as the setting's choice, not its index.
    EXPECT_NE(std::find(applied.begin(), applied.end(), "radius_mode=travel"), applied.end())
        << j.dump();
    // Every preset setting is either applied or reported as skipped.
    EXPECT_EQ(applied.size() + skipped.size(), 9u) << j.dump();
    EXPECT_NE(std::find(applied.begin(), applied.end(), "splat_resolution=1/2"), applied.end())
        << j.dump();
    // The thesis shades direct light at pixel centres.
    EXPECT_NE(std::find(applied.begin(), applied.end(), "edge_samples=0"), applied.end())
        << j.dump();
}

TEST_F(BenchTest, AnimateTimesTheSceneUpdateFirst) {
    const std::string scene = std::string(ISPM_ASSET_DIR) + "/scenes/dynamic.json";
    const nlohmann::json still = runJson(scene + kSmallRun);
    const nlohmann::json moving = runJson(scene + kSmallRun + " --animate");
    ASSERT_FALSE(still.is_discarded());
    ASSERT_FALSE(moving.is_discarded());
    EXPECT_EQ(still["animate"], false);
    EXPECT_EQ(moving["animate"], true);
    // The update runs before the passes: its row comes first, and only when animating.
    EXPECT_NE(still["passes"][0]["name"], "scene update");
    EXPECT_EQ(moving["passes"][0]["name"], "scene update");
    EXPECT_EQ(moving["passes"].size(), still["passes"].size() + 1);
    const RunResult r = run("bench " + mScene + " --animate --csv x.csv", true);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--animate"), std::string::npos) << r.output;
}

TEST_F(BenchTest, FlickerIsZeroForAStillSceneAndNotForAMovingCube) {
    // A still scene renders the same photons every frame (the seed does not move without
    // accumulation): nothing flickers, to the last bit.
    const nlohmann::json still = runJson(mScene + kSmallRun + " --flicker 3");
    ASSERT_FALSE(still.is_discarded());
    EXPECT_EQ(still["frames"], 3);
    EXPECT_EQ(still["flicker"]["all"], 0.0) << still.dump();
    EXPECT_GT(still["flicker"]["pixels"], 0) << "no surface pixel measured";
    // The moving cube changes the photons' paths, so its light moves; with the cube's
    // neighbourhood left out, what remains is the rest of the room's flicker.
    const std::string cube = std::string(ISPM_ASSET_DIR) + "/scenes/moving_cube.json";
    const nlohmann::json moving = runJson(cube + kSmallRun + " --animate --flicker 4");
    ASSERT_FALSE(moving.is_discarded());
    EXPECT_GT(moving["flicker"]["all"].get<double>(), 0.0) << moving.dump();
    EXPECT_LT(moving["flicker"]["away_pixels"], moving["flicker"]["pixels"]) << moving.dump();
    EXPECT_EQ(moving["flicker"]["away_m"], 0.5);
    // Bad values: one line, exit 2.
    for (const std::string& args :
         {mScene + " --flicker 1", mScene + " --flicker 3 --flicker-away -1"}) {
        const RunResult r = run("bench " + args, true);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
}

TEST_F(BenchTest, BadCountsExitTwoWithOneLine) {
    for (const std::string& args :
         {mScene + " --frames 0", mScene + " --frames abc", mScene + " --frames -3"}) {
        const RunResult r = run("bench " + args, true);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_NE(r.output.find("--frames"), std::string::npos) << r.output;
    }
    RunResult r = run("bench " + mScene + " --warmup -1", true);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--warmup"), std::string::npos) << r.output;
    r = run("bench " + mScene + " --preset fastest", true);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--preset"), std::string::npos) << r.output;
    r = run("bench --frames 1", true);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--preset"), std::string::npos) << "says SCENE needs --preset";
}

} // namespace
} // namespace ispm::test
