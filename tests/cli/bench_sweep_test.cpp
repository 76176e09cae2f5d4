// `ispm bench --sweep` contract: a tiny sweep writes one CSV row per configuration and per path-
// tracer checkpoint with finite numbers, tools/plot_bench.py turns it into a PNG, and bad inputs
// (reference size, unknown setting, missing file) exit 2 with one line before any rendering; the
// same for tools/converge.sh and tools/plot_converge.py (error against accumulated frames).
#include "image/image_io.h"
#include "support/run_ispm.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace ispm::test {
namespace {

RunResult runCommand(const std::string& command, bool mergeStderr) {
    return ispm::test::runCommand(command, mergeStderr ? Stderr::Merge : Stderr::Discard);
}

RunResult runIspm(const std::string& args, bool mergeStderr) {
    return ispm::test::runIspm(args, mergeStderr ? Stderr::Merge : Stderr::Discard);
}

// A closed grey room (floor, ceiling, three walls and a front wall behind the camera) with a
// point light: every bounce stays inside, so indirect light is a large part of the image.
constexpr const char* kRoomScene = R"({
  "camera": {"position": [0, 1, 1.6], "target": [0, 1, 0], "up": [0, 1, 0], "fov_y_deg": 60},
  "materials": {"grey": {"diffuse": [0.6, 0.6, 0.6]}},
  "objects": [
    {"type": "box", "min": [-1, -0.1, -1], "max": [1, 0, 2], "material": "grey"},
    {"type": "box", "min": [-1, 2, -1], "max": [1, 2.1, 2], "material": "grey"},
    {"type": "box", "min": [-1, 0, -1.1], "max": [1, 2, -1], "material": "grey"},
    {"type": "box", "min": [-1, 0, 2], "max": [1, 2, 2.1], "material": "grey"},
    {"type": "box", "min": [-1.1, 0, -1], "max": [-1, 2, 2], "material": "grey"},
    {"type": "box", "min": [1, 0, -1], "max": [1.1, 2, 2], "material": "grey"}
  ],
  "lights": [{"type": "point", "position": [0.3, 1.7, -0.2], "intensity": [2, 2, 2]}]
})";

constexpr int kSizePx = 24;
constexpr int kReferenceSpp = 16;
const std::string kSize =
    " --width " + std::to_string(kSizePx) + " --height " + std::to_string(kSizePx);
// Small light cameras: the default 1024^2 faces would dominate every frame on llvmpipe.
constexpr const char* kSmallLights = " --set shadow_map_size=64";
constexpr const char* kTinySweep = " --sweep photons=2000,4000 --sweep radius_scale=1,2"
                                   " --frames 1 --warmup 1 --reference-spp-max 4";
constexpr size_t kIspmRows = 4;             // 2 photon budgets x 2 radius scales
const std::vector<int> kTracerSpp{1, 2, 4}; // powers of two up to --reference-spp-max
// A 640x480 chart with axes, labels and a legend compresses to tens of kB; an empty or broken
// figure is far smaller.
constexpr std::uintmax_t kMinPngBytes = 10000;

using CsvRow = std::map<std::string, std::string>;

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ','))
        cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back(); // a trailing empty cell
    return cells;
}

// Rows as column -> cell; every row must have as many cells as the header.
std::vector<CsvRow> readCsv(const std::string& path, std::vector<std::string>& header) {
    std::ifstream in(path);
    std::string line;
    std::vector<CsvRow> rows;
    if (!std::getline(in, line)) return rows;
    header = splitCsvLine(line);
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = splitCsvLine(line);
        EXPECT_EQ(cells.size(), header.size()) << line;
        CsvRow row;
        for (size_t i = 0; i < std::min(cells.size(), header.size()); ++i)
            row[header[i]] = cells[i];
        rows.push_back(row);
    }
    return rows;
}

double toNumber(const CsvRow& row, const std::string& column) {
    const auto it = row.find(column);
    if (it == row.end() || it->second.empty()) return std::nan("");
    try {
        size_t used = 0;
        const double value = std::stod(it->second, &used);
        return used == it->second.size() ? value : std::nan("");
    } catch (const std::exception&) {
        return std::nan("");
    }
}

bool isPositive(double value) {
    return std::isfinite(value) && value > 0.0;
}

class BenchSweepTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mDir = std::filesystem::temp_directory_path() /
               ("ispm_bench_sweep_test_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        std::filesystem::create_directories(mDir);
        mScene = (mDir / "room.json").string();
        std::ofstream(mScene) << kRoomScene;
    }
    void TearDown() override { std::filesystem::remove_all(mDir); }

    // `render --mode reference` of the room at kSizePx and kReferenceSpp, plus `extra`, to `path`.
    RunResult renderReference(const std::string& path, const std::string& extra) {
        return runIspm("render " + mScene + " --mode reference --spp " +
                           std::to_string(kReferenceSpp) + extra + kSize + " -o " + path,
                       true);
    }

    // One line, naming `fragment`, exit 2.
    void expectBadInput(const std::string& args, const std::string& fragment) {
        const RunResult r = runIspm("bench " + args, true);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_NE(r.output.find(fragment), std::string::npos)
            << "missing '" << fragment << "' in: " << r.output;
    }

    std::filesystem::path mDir;
    std::string mScene;
};

TEST_F(BenchSweepTest, TinySweepWritesCsvWithExpectedRowsAndPngChart) {
    const std::string reference = (mDir / "reference.pfm").string();
    const RunResult render = renderReference(reference, "");
    ASSERT_EQ(render.exitCode, 0) << render.output;

    const std::string csvPath = (mDir / "sweep.csv").string();
    const RunResult sweep = runIspm("bench " + mScene + kSize + kSmallLights + " --reference " +
                                        reference + kTinySweep + " --csv " + csvPath,
                                    false);
    ASSERT_EQ(sweep.exitCode, 0) << sweep.output;
    EXPECT_NE(sweep.output.find("speedup"), std::string::npos) << sweep.output;
    // stdout is not a terminal here: no progress bar may leak into it.
    EXPECT_EQ(sweep.output.find('\r'), std::string::npos);

    std::vector<std::string> header;
    const std::vector<CsvRow> rows = readCsv(csvPath, header);
    for (const char* column :
         {"kind", "spp", "width", "height", "bounces", "photons", "radius_scale", "total_ms",
          "relmse_total", "relmse_indirect", "ssim", "photons_emitted", "photons_bounced",
          "photons_stored", "photons_overflow"}) {
        EXPECT_NE(std::find(header.begin(), header.end(), column), header.end()) << column;
    }
    std::vector<std::string> passColumns;
    for (const std::string& c : header) {
        if (c.size() > 3 && c.ends_with("_ms") && c != "total_ms") passColumns.push_back(c);
    }
    EXPECT_FALSE(passColumns.empty()) << "no per-pass columns";

    std::set<std::pair<double, double>> configs; // (photons, radius_scale)
    std::vector<int> tracerSpp;
    double lastTracerMs = 0.0;
    for (const CsvRow& row : rows) {
        EXPECT_TRUE(isPositive(toNumber(row, "total_ms"))) << row.at("kind");
        EXPECT_TRUE(isPositive(toNumber(row, "relmse_total"))) << row.at("kind");
        const double ssim = toNumber(row, "ssim");
        EXPECT_TRUE(std::isfinite(ssim) && ssim > 0.0 && ssim <= 1.0) << ssim;
        EXPECT_EQ(toNumber(row, "width"), kSizePx);
        EXPECT_EQ(toNumber(row, "height"), kSizePx);
        if (row.at("kind") == "ispm") {
            configs.insert({toNumber(row, "photons"), toNumber(row, "radius_scale")});
            EXPECT_TRUE(isPositive(toNumber(row, "relmse_indirect")));
            EXPECT_TRUE(isPositive(toNumber(row, "photons_emitted")));
            EXPECT_TRUE(isPositive(toNumber(row, "photons_stored")));
            for (const std::string& c : passColumns) {
                const double ms = toNumber(row, c);
                EXPECT_TRUE(std::isfinite(ms) && ms >= 0.0) << c << " = " << row.at(c);
            }
        } else {
            ASSERT_EQ(row.at("kind"), "reference");
            tracerSpp.push_back(static_cast<int>(toNumber(row, "spp")));
            // Cumulative: every checkpoint includes the samples before it.
            EXPECT_GT(toNumber(row, "total_ms"), lastTracerMs);
            lastTracerMs = toNumber(row, "total_ms");
        }
    }
    EXPECT_EQ(rows.size(), kIspmRows + kTracerSpp.size());
    const std::set<std::pair<double, double>> expected{{2000, 1}, {2000, 2}, {4000, 1}, {4000, 2}};
    EXPECT_EQ(configs, expected);
    EXPECT_EQ(tracerSpp, kTracerSpp);

    const std::filesystem::path script =
        std::filesystem::path(ISPM_TEST_DATA_DIR).parent_path() / "tools" / "plot_bench.py";
    const std::string png = (mDir / "chart.png").string();
    const RunResult plot =
        runCommand("/usr/bin/python3 " + script.string() + " " + csvPath + " " + png, true);
    ASSERT_EQ(plot.exitCode, 0) << plot.output;
    ASSERT_TRUE(std::filesystem::exists(png));
    EXPECT_GT(std::filesystem::file_size(png), kMinPngBytes);
    std::ifstream in(png, std::ios::binary);
    std::array<char, 8> magic{};
    in.read(magic.data(), magic.size());
    EXPECT_EQ(std::string(magic.data(), magic.size()), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_F(BenchSweepTest, TracerCurveDrawsOtherSamplesThanTheReference) {
    // The sweep's path tracer runs to the reference's own sample count with the same seed and
    // bounces settings. Drawn apart from the reference, its error at R samples is 2 s^2 / R
    // against 3 s^2 / R at R/2 (each image's variance plus the reference's): a ratio of 2/3. Had
    // it drawn the reference's own samples, the image at R would be the reference: error 0.
    const std::string reference = (mDir / "reference.pfm").string();
    const RunResult render = renderReference(reference, " --bounces 3");
    ASSERT_EQ(render.exitCode, 0) << render.output;
    const std::string csvPath = (mDir / "sweep.csv").string();
    const RunResult sweep =
        runIspm("bench " + mScene + kSize + kSmallLights + " --reference " + reference +
                    " --sweep photons=2000 --frames 1 --warmup 0 --reference-spp-max " +
                    std::to_string(kReferenceSpp) + " --csv " + csvPath,
                false);
    ASSERT_EQ(sweep.exitCode, 0) << sweep.output;
    std::vector<std::string> header;
    std::map<int, double> tracerError; // by spp
    for (const CsvRow& row : readCsv(csvPath, header)) {
        if (row.at("kind") == "reference")
            tracerError[static_cast<int>(toNumber(row, "spp"))] = toNumber(row, "relmse_total");
    }
    ASSERT_EQ(tracerError.count(kReferenceSpp), 1u);
    ASSERT_EQ(tracerError.count(kReferenceSpp / 2), 1u);
    ASSERT_TRUE(isPositive(tracerError[kReferenceSpp / 2]));
    // 0.4: well below 2/3 for the noise of a 24x24 image's error (0.67 read), far above 0.
    EXPECT_GT(tracerError[kReferenceSpp] / tracerError[kReferenceSpp / 2], 0.4)
        << tracerError[kReferenceSpp] << " at " << kReferenceSpp << " spp";
}

TEST_F(BenchSweepTest, ConvergeScriptWritesRowsAndChart) {
    // tools/converge.sh renders --accumulate N for each N against a reference's indirect light;
    // tools/plot_converge.py draws the rows.
    const std::string ref3 = (mDir / "ref3.pfm").string();
    const std::string ref0 = (mDir / "ref0.pfm").string();
    for (const auto& [path, bounces] : {std::pair{ref3, 3}, std::pair{ref0, 0}}) {
        const RunResult r = renderReference(path, " --bounces " + std::to_string(bounces));
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const std::filesystem::path tools =
        std::filesystem::path(ISPM_TEST_DATA_DIR).parent_path() / "tools";
    const std::string csvPath = (mDir / "converge.csv").string();
    std::ofstream(csvPath) << "label,frames,energy,rel_rmse4\n";
    const RunResult converge =
        runCommand("bash " + (tools / "converge.sh").string() + " " + ISPM_EXECUTABLE + " room " +
                       mScene + " '' " + ref3 + " " + ref0 + " 1 4 -- --set photons=4000" +
                       kSmallLights + " >> " + csvPath,
                   true);
    ASSERT_EQ(converge.exitCode, 0) << converge.output;
    std::vector<std::string> header;
    const std::vector<CsvRow> rows = readCsv(csvPath, header);
    ASSERT_EQ(rows.size(), 2u);
    for (const CsvRow& row : rows) {
        EXPECT_EQ(row.at("label"), "room");
        // Indirect light of the closed room: within 30% of the 16 spp reference's (4,000
        // photons and 16 spp are both noisy at 24 px), and a finite error.
        EXPECT_NEAR(toNumber(row, "energy"), 1.0, 0.3) << row.at("frames");
        EXPECT_TRUE(isPositive(toNumber(row, "rel_rmse4"))) << row.at("frames");
    }
    EXPECT_EQ(toNumber(rows[0], "frames"), 1.0);
    EXPECT_EQ(toNumber(rows[1], "frames"), 4.0);
    const std::string png = (mDir / "converge.png").string();
    const RunResult plot = runCommand("/usr/bin/python3 " + (tools / "plot_converge.py").string() +
                                          " " + csvPath + " " + png,
                                      true);
    ASSERT_EQ(plot.exitCode, 0) << plot.output;
    EXPECT_GT(std::filesystem::file_size(png), kMinPngBytes);
    // Bad input: a frame count that is not one, a CSV that is not the script's.
    const RunResult badFrames =
        runCommand("bash " + (tools / "converge.sh").string() + " " + ISPM_EXECUTABLE + " room " +
                       mScene + " '' " + ref3 + " " + ref0 + " 0",
                   true);
    EXPECT_EQ(badFrames.exitCode, 2) << badFrames.output;
    EXPECT_NE(badFrames.output.find("frame count '0'"), std::string::npos) << badFrames.output;
    const std::string wrong = (mDir / "wrong.csv").string();
    std::ofstream(wrong) << "kind,spp\nispm,1\n";
    const RunResult badCsv = runCommand(
        "/usr/bin/python3 " + (tools / "plot_converge.py").string() + " " + wrong + " " + png,
        true);
    EXPECT_EQ(badCsv.exitCode, 2) << badCsv.output;
    EXPECT_NE(badCsv.output.find("expected columns"), std::string::npos) << badCsv.output;
}

TEST_F(BenchSweepTest, RoundsTimeTheSameFramesAgain) {
    // --rounds 3 passes over the configurations three times: it says so, and measures the same
    // frames (the same seeds: the same errors, to float round-off of the photons' order) and the
    // same tracer curve as one round.
    const std::string reference = (mDir / "reference.pfm").string();
    ASSERT_EQ(renderReference(reference, "").exitCode, 0);
    auto sweep = [&](int rounds) {
        const std::string csvPath = (mDir / ("rounds" + std::to_string(rounds) + ".csv")).string();
        const RunResult r =
            runIspm("bench " + mScene + kSize + kSmallLights + " --reference " + reference +
                        " --sweep photons=2000,4000 --frames 1 --warmup 0 "
                        "--reference-spp-max 4 --rounds " +
                        std::to_string(rounds) + " --csv " + csvPath,
                    false);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find(" x 3 rounds") != std::string::npos, rounds == 3) << r.output;
        std::vector<std::string> header;
        std::map<std::string, double> errors; // kind + photons or spp -> relmse_total
        for (const CsvRow& row : readCsv(csvPath, header)) {
            const bool ispm = row.at("kind") == "ispm";
            errors[row.at("kind") + (ispm ? row.at("photons") : row.at("spp"))] =
                toNumber(row, "relmse_total");
        }
        return errors;
    };
    const std::map<std::string, double> one = sweep(1);
    const std::map<std::string, double> three = sweep(3);
    ASSERT_EQ(one.size(), 5u); // 2 configurations, the tracer at 1, 2 and 4 spp
    ASSERT_EQ(three.size(), one.size());
    for (const auto& [row, error] : one) {
        ASSERT_TRUE(three.contains(row)) << row;
        EXPECT_TRUE(isPositive(error)) << row;
        // Float sums of photons appended in another order: 1e-4 of the error at most.
        EXPECT_NEAR(three.at(row), error, 1e-4 * error) << row;
    }
}

TEST_F(BenchSweepTest, BadInputsExitTwoWithOneLine) {
    // Written directly: these runs must stop at the checks, so the image content does not matter.
    const std::string reference = (mDir / "reference.pfm").string();
    writeImage(reference, Image(kSizePx, kSizePx, glm::vec3(1.0f)));
    const std::string csv = " --csv " + (mDir / "out.csv").string();
    expectBadInput(mScene + " --width 32 --height 32 --reference " + reference +
                       " --sweep photons=1000" + csv,
                   "24x24");
    expectBadInput(mScene + kSize + " --reference " + reference + " --sweep width=24,32" + csv,
                   "--sweep width");
    expectBadInput(mScene + kSize + " --reference " + reference + " --sweep photon=1000" + csv,
                   "unknown setting 'photon'");
    expectBadInput(mScene + kSize + " --reference " + reference + " --sweep photons=1000,-5" + csv,
                   "photons");
    expectBadInput(mScene + kSize + " --reference " + (mDir / "missing.pfm").string() +
                       " --sweep photons=1000" + csv,
                   "missing.pfm");
    expectBadInput(mScene + kSize + " --sweep photons=1000" + csv, "--reference");
    expectBadInput(mScene + kSize + " --reference " + reference + " --sweep photons=1000" + csv +
                       " --reference-spp-max 0",
                   "--reference-spp-max");
    expectBadInput(mScene + kSize + " --reference " + reference + " --sweep photons=1000" + csv +
                       " --rounds 0",
                   "--rounds");
    expectBadInput(mScene + kSize + " --rounds 2", "--rounds");
    EXPECT_FALSE(std::filesystem::exists(mDir / "out.csv")) << "bad input must not write a CSV";
}

} // namespace
} // namespace ispm::test
