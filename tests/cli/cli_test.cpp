// The executable's contract with users: bad input gives one line naming the file and the JSON path
// (or the flag) and exit code 2; good input renders a non-black image.
#include "image/image_io.h"
#include "image/metrics.h"
#include "support/gltf_scenes.h"
#include "support/run_ispm.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace ispm::test {
namespace {

RunResult run(const std::string& args) {
    return runIspm(args);
}

class CliTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mDir = std::filesystem::temp_directory_path() /
               ("ispm_cli_test_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        std::filesystem::create_directories(mDir);
    }
    void TearDown() override { std::filesystem::remove_all(mDir); }
    std::string writeScene(const std::string& name, const std::string& text) {
        const std::filesystem::path p = mDir / name;
        std::ofstream(p) << text;
        return p.string();
    }
    // One line, naming every given fragment, exit 2.
    void expectBadInput(const std::string& args, std::initializer_list<std::string> fragments) {
        const RunResult r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        for (const std::string& f : fragments) {
            EXPECT_NE(r.output.find(f), std::string::npos)
                << "missing '" << f << "' in: " << r.output;
        }
    }
    std::filesystem::path mDir;
};

constexpr const char* kGoodScene = R"({
  "camera": {"position": [0, 1, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 50},
  "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
  "objects": [{"type": "box", "min": [-1, -0.1, -1], "max": [1, 0, 1], "material": "grey"}],
  "lights": [{"type": "point", "position": [0, 1, 0], "intensity": [2, 2, 2]}]
})";

TEST_F(CliTest, RendersPngAndPfm) {
    const std::string scene = writeScene("good.json", kGoodScene);
    const std::string png = (mDir / "out.png").string();
    RunResult r = run("render " + scene + " -o " + png + " --width 32 --height 24");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("direct"), std::string::npos) << "per-pass times are printed";
    const Image image = readImage(png);
    EXPECT_EQ(image.width, 32);
    EXPECT_EQ(image.height, 24);
    float maxValue = 0.0f;
    for (const glm::vec3& p : image.pixels)
        maxValue = std::max(maxValue, p.x);
    EXPECT_GT(maxValue, 0.5f) << "not a black image";

    const std::string pfm = (mDir / "out.pfm").string();
    r = run("render " + scene + " -o " + pfm + " --width 8 --height 8 --aov direct -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readImage(pfm).width, 8);
}

TEST_F(CliTest, RendersGltfFilesAndRejectsBrokenOnes) {
    const std::string gltf = (mDir / "room.gltf").string();
    CheckerRoom room;
    room.cameraPositionM = {0.0f, 1.5f, 0.0f};
    writeCheckerRoomGltf(gltf, room);
    const std::string png = (mDir / "room.png").string();
    const RunResult r = run("render " + gltf + " -o " + png + " --width 24 --height 24");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Image image = readImage(png);
    float maxValue = 0.0f;
    for (const glm::vec3& p : image.pixels)
        maxValue = std::max(maxValue, p.x);
    EXPECT_GT(maxValue, 0.5f) << "the spot lights the floor the camera looks at";
    const std::string bad = writeScene("bad.gltf", R"({"asset": {"version": "2.0"},
                       "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [2, 0, 0, 1]}}]})");
    expectBadInput("render " + bad + " -o " + png,
                   {"bad.gltf: /materials/0/pbrMetallicRoughness/baseColorFactor/0: expected"});
}

TEST_F(CliTest, WritesPhotonBufferImages) {
    // Each photon AOV is a PNG of points over the dimmed frame: brighter than the backdrop alone
    // (30% of a frame whose display values reach 1), and refused where it cannot be written.
    // A wall behind the floor: photons the floor reflects land on it (result photons).
    std::string text = kGoodScene;
    const std::string floor = "\"material\": \"grey\"}";
    text.replace(text.find(floor), floor.size(),
                 floor + ", {\"type\": \"box\", \"min\": [-1, 0, -1.1], \"max\": [1, 1, -1], "
                         "\"material\": \"grey\"}");
    const std::string scene = writeScene("wall.json", text);
    for (const char* aov :
         {"bounce_direction", "bounce_power", "result_direction", "result_power"}) {
        const std::string png = (mDir / (std::string(aov) + ".png")).string();
        const RunResult r =
            run("render " + scene + " -o " + png + " --width 32 --height 24 -q --aov " + aov);
        ASSERT_EQ(r.exitCode, 0) << aov << ": " << r.output;
        const Image image = readImage(png);
        float maxValue = 0.0f;
        for (const glm::vec3& p : image.pixels)
            maxValue = std::max({maxValue, p.x, p.y, p.z});
        EXPECT_GT(maxValue, 0.4f) << aov << ": no point is brighter than the dimmed backdrop";
    }
    expectBadInput("render " + scene + " -o x.pfm --aov result_power", {"--aov", ".png"});
    expectBadInput("render " + scene + " -o x.png --aov result_power --bounces 0",
                   {"--aov", "photons"});
    expectBadInput("render " + scene + " -o x.exr --aov bounce_direction --mode reference",
                   {"--aov"});
}

TEST_F(CliTest, RendersSequencesAlongACameraPath) {
    // The camera walks 2 m in 1 s: three frames at 2 frames/s are the scene at 0, 0.5 and 1 s,
    // each as a single render at that --time would draw it.
    std::string text = kGoodScene;
    const std::string camera =
        R"("camera": {"position": [0, 1, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 50})";
    ASSERT_NE(text.find(camera), std::string::npos);
    text.replace(text.find(camera), camera.size(),
                 R"("camera": {"fov_y_deg": 50, "path": [)"
                 R"({"time_s": 0, "position": [0, 1, 3], "target": [0, 0, 0]},)"
                 R"({"time_s": 1, "position": [2, 1, 2], "target": [0, 0, 0]}]})");
    const std::string scene = writeScene("walk.json", text);
    const std::string size = " --width 32 --height 24 -q";
    RunResult r = run("render " + scene + " -o " + (mDir / "walk_%03d.pfm").string() +
                      " --frames 3 --fps 2" + size + " --set eye_adaptation_s=0.5");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* name : {"walk_000.pfm", "walk_001.pfm", "walk_002.pfm"})
        EXPECT_TRUE(std::filesystem::exists(mDir / name)) << name;
    EXPECT_FALSE(std::filesystem::exists(mDir / "walk_003.pfm"));
    r = run("render " + scene + " -o " + (mDir / "at1.pfm").string() + " --time 1" + size);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Image single = readImage((mDir / "at1.pfm").string());
    // The same frame up to float round-off where buffers of the earlier frames are reused.
    EXPECT_LT(computeRelRmse(readImage((mDir / "walk_002.pfm").string()), single, 1), 1e-4);
    // ... and another view than the first frame's.
    EXPECT_GT(computeRelRmse(readImage((mDir / "walk_000.pfm").string()), single, 1), 0.1);

    const std::string out = " -o " + (mDir / "f_%d.png").string();
    expectBadInput("render " + scene + " -o x.png --frames 3", {"--output", "frame number"});
    expectBadInput("render " + scene + " -o x_%d_%d.png --frames 3", {"--output"});
    expectBadInput("render " + scene + " -o x_%s.png --frames 3", {"--output", "%04d"});
    expectBadInput("render " + scene + out + " --frames 0", {"--frames"});
    expectBadInput("render " + scene + out + " --frames 2 --fps 0", {"--fps"});
    expectBadInput("render " + scene + out + " --frames 2 --fps nan", {"--fps"});
    expectBadInput("render " + scene + " -o x_%d.pfm --frames 2 --mode reference", {"--frames"});
    expectBadInput("render " + scene + out + " --set eye_adaptation_s=-1", {"eye_adaptation_s"});
}

TEST_F(CliTest, ClipPlanesPastTheDepthRangeStillRenderWithAWarning) {
    // near 1e-8 m, far 3e38 m: every depth rounded onto the far plane and the image was black.
    std::string text = kGoodScene;
    const std::string fov = "\"fov_y_deg\": 50";
    text.replace(text.find(fov), fov.size(), fov + ", \"near\": 1e-8, \"far\": 3e38");
    const std::string scene = writeScene("planes.json", text);
    const std::string png = (mDir / "planes.png").string();
    const RunResult r = run("render " + scene + " -o " + png + " --width 32 --height 24 -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("ispm: warning: the camera's near plane (1e-08 m) is raised"),
              std::string::npos)
        << r.output;
    float maxValue = 0.0f;
    for (const glm::vec3& p : readImage(png).pixels)
        maxValue = std::max(maxValue, p.x);
    EXPECT_GT(maxValue, 0.5f) << "not a black image";
}

TEST_F(CliTest, SplatsWiderThanTheSceneAreWarnedAbout) {
    // Travel radii 30 times their derived size are wider than this 2.8 m scene: the render
    // still runs (exit 0) but says why its indirect light fades. The default radii say nothing.
    const std::string scene = writeScene("good.json", kGoodScene);
    const std::string base = "render " + scene + " -o " + (mDir / "out.pfm").string() +
                             " --width 16 --height 16 --aov indirect -q";
    RunResult r = run(base + " --set radius_mode=travel --set radius_scale=30");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("ispm: warning: splat discs reach a radius of"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("radius_scale"), std::string::npos) << r.output;
    for (const char* fine : {"", " --set radius_mode=travel", " --set radius_scale=30"}) {
        r = run(base + fine);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << fine << ": " << r.output;
    }
}

TEST_F(CliTest, BadSceneFilesExitTwoWithFileAndPath) {
    expectBadInput("render " + writeScene("broken.json", "{ \"camera\": ") + " -o x.png",
                   {"broken.json"});
    std::string text = kGoodScene;
    text.replace(text.find("\"point\""), 7, "\"laser\"");
    expectBadInput("render " + writeScene("laser.json", text) + " -o x.png",
                   {"laser.json", "/lights/0/type"});
    text = kGoodScene;
    text.replace(text.find("\"fov_y_deg\": 50"), 15, "\"fov_y_deg\": -5");
    expectBadInput("render " + writeScene("fov.json", text) + " -o x.png",
                   {"fov.json", "/camera/fov_y_deg"});
    text = kGoodScene;
    text.replace(text.find("[2, 2, 2]"), 9, "\"bright\"");
    expectBadInput("render " + writeScene("str.json", text) + " -o x.png",
                   {"str.json", "/lights/0/intensity"});
    text = kGoodScene;
    text.replace(text.find("{\"type\": \"box\""), 0,
                 "{\"type\": \"mesh\", \"obj\": \"missing.obj\"}, ");
    expectBadInput("render " + writeScene("obj.json", text) + " -o x.png",
                   {"obj.json", "missing.obj"});
    expectBadInput("render " + (mDir / "nothere.json").string() + " -o x.png", {"nothere.json"});
    // A normal of zero length: the OBJ file and the vn's index.
    std::ofstream(mDir / "flat_vn.obj")
        << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n";
    text = kGoodScene;
    text.replace(text.find("{\"type\": \"box\""), 0,
                 "{\"type\": \"mesh\", \"obj\": \"flat_vn.obj\", \"material\": \"grey\"}, ");
    expectBadInput("render " + writeScene("vn.json", text) + " -o x.png",
                   {"vn.json", "/objects/0/obj", "flat_vn.obj", "vn 1", "non-zero length"});
}

TEST_F(CliTest, BadCommandLineValuesExitTwo) {
    const std::string scene = writeScene("good.json", kGoodScene);
    expectBadInput("render " + scene + " -o x.png --width 0", {"--width"});
    expectBadInput("render " + scene + " -o x.png --width abc", {"--width"});
    expectBadInput("render " + scene + " -o x.bmp", {"x.bmp"});
    expectBadInput("render " + scene + " -o x.png --set nosuch=1", {"nosuch"});
    expectBadInput("render " + scene + " -o x.png --set gamma=-1", {"gamma"});
    expectBadInput("render " + scene + " -o x.png --set tonemap=sepia", {"tonemap", "sepia"});
    // Post-processing: a shutter longer than the frame, a negative lens, bloom that would give
    // more light than a pixel has.
    expectBadInput("render " + scene + " -o x.png --set motion_blur_shutter=1.5",
                   {"motion_blur_shutter"});
    expectBadInput("render " + scene + " -o x.png --set dof_aperture_m=-0.1", {"dof_aperture_m"});
    expectBadInput("render " + scene + " -o x.png --set dof_focus_m=0", {"dof_focus_m"});
    expectBadInput("render " + scene + " -o x.png --set bloom_intensity=2", {"bloom_intensity"});
    expectBadInput("render " + scene + " -o x.png --set bloom_radius_px=nan", {"bloom_radius_px"});
    expectBadInput("render " + scene + " -o x.pfm --aov sideways", {"--aov"});
    expectBadInput("render " + scene + " -o x.png --time -1", {"--time"});
    // Outputs that cannot be written are refused before the render (exit 2), not after it.
    expectBadInput("render " + scene + " -o " + (mDir / "no_folder" / "x.png").string(),
                   {"--output", "no_folder"});
    expectBadInput("render " + scene + " -o " + mDir.string() + "/", {"--output"});
    std::filesystem::create_directories(mDir / "taken.png");
    expectBadInput("render " + scene + " -o " + (mDir / "taken.png").string(),
                   {"--output", "taken.png", "folder"});
    expectBadInput("render " + scene + " -o x.png --time soon", {"--time"});
    // --bounces reaches the reference's default of 64 in both modes, no further.
    expectBadInput("render " + scene + " -o x.png --bounces 65", {"--bounces", "64"});
    expectBadInput("frobnicate", {"frobnicate"});
}

TEST_F(CliTest, CompareReportsMetricsAndThreshold) {
    const std::string scene = writeScene("good.json", kGoodScene);
    const std::string a = (mDir / "a.pfm").string();
    const std::string b = (mDir / "b.pfm").string();
    ASSERT_EQ(run("render " + scene + " -o " + a + " --width 16 --height 16 -q").exitCode, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --width 16 --height 16 -q --set exposure=1")
                  .exitCode,
              0);
    RunResult same = run("compare " + a + " " + a + " --max-relmse 0");
    EXPECT_EQ(same.exitCode, 0) << same.output;
    EXPECT_NE(same.output.find("SSIM"), std::string::npos);
    // Exposure does not change linear output, so a and b agree too.
    EXPECT_EQ(run("compare " + a + " " + b + " --max-relmse 0").exitCode, 0);
    const std::string c = (mDir / "c.pfm").string();
    ASSERT_EQ(
        run("render " + scene + " -o " + c + " --width 16 --height 16 -q --set shadow_bias=50")
            .exitCode,
        0);
    expectBadInput("compare " + a + " " + (mDir / "none.pfm").string(), {"none.pfm"});
    // A folder (read as a huge file before: std::bad_alloc) and a threshold that is no number
    // (nan passed the range check and turned the check off).
    expectBadInput("compare " + mDir.string() + " " + a, {mDir.string(), "folder"});
    expectBadInput("compare " + a + " " + b + " --max-relmse nan", {"--max-relmse"});
}

TEST_F(CliTest, CompareMaskRestrictsThePixels) {
    constexpr int kSize = 8;
    Image a(kSize, kSize, glm::vec3(1.0f));
    Image b = a;
    Image mask(kSize, kSize, glm::vec3(0.0f));
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (x >= kSize / 2) b.at(x, y) = glm::vec3(2.0f);   // differs on the right half
            if (x < kSize / 2) mask.at(x, y) = glm::vec3(1.0f); // compares the left half
        }
    }
    const std::string pa = (mDir / "a.pfm").string();
    const std::string pb = (mDir / "b.pfm").string();
    const std::string pm = (mDir / "mask.png").string();
    writeImage(pa, a);
    writeImage(pb, b);
    writeImage(pm, mask);
    EXPECT_EQ(run("compare " + pa + " " + pb + " --max-relmse 0").exitCode, 1);
    const RunResult masked = run("compare " + pa + " " + pb + " --mask " + pm + " --max-relmse 0");
    EXPECT_EQ(masked.exitCode, 0) << masked.output;
    EXPECT_NE(masked.output.find("pixels      32"), std::string::npos) << masked.output;
    writeImage((mDir / "small.png").string(), Image(2, 2));
    expectBadInput("compare " + pa + " " + pb + " --mask " + (mDir / "small.png").string(),
                   {"small.png"});
}

TEST_F(CliTest, CompareMinusGivesTheQualityFiguresOfADifference) {
    // B - C is 1 everywhere but a quarter of the pixels, where it is 0 (left out as black); A is
    // 1.5 where B - C is 1: energy 1.5, rel RMSE 0.5 on 4x4 blocks.
    constexpr int kSize = 8;
    Image a(kSize, kSize, glm::vec3(1.5f));
    Image b(kSize, kSize, glm::vec3(3.0f));
    Image c(kSize, kSize, glm::vec3(2.0f));
    for (int y = 0; y < kSize / 2; ++y) {
        for (int x = 0; x < kSize / 2; ++x)
            c.at(x, y) = glm::vec3(3.0f);
    }
    const std::string pa = (mDir / "a.pfm").string();
    const std::string pb = (mDir / "b.pfm").string();
    const std::string pc = (mDir / "c.pfm").string();
    writeImage(pa, a);
    writeImage(pb, b);
    writeImage(pc, c);
    const RunResult r = run("compare " + pa + " " + pb + " --minus " + pc);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("energy        1.500000 (mean ratio over the 48 pixels"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("rel RMSE 4x4  0.500000"), std::string::npos) << r.output;
    writeImage((mDir / "small.pfm").string(), Image(2, 2));
    expectBadInput("compare " + pa + " " + pb + " --minus " + (mDir / "small.pfm").string(),
                   {"small.pfm"});
}

TEST_F(CliTest, HelpOnEverySubcommand) {
    for (const char* sub : {"render", "export", "info", "compare", "bench", "view", "settings"}) {
        const RunResult r = run(std::string(sub) + " --help");
        EXPECT_EQ(r.exitCode, 0) << sub;
        EXPECT_NE(r.output.find("Usage"), std::string::npos) << sub;
    }
}

TEST_F(CliTest, ExportWritesObjAndMtl) {
    const std::string scene = writeScene("good.json", kGoodScene);
    const std::string obj = (mDir / "out.obj").string();
    const RunResult r = run("export " + scene + " -o " + obj);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(obj));
    EXPECT_TRUE(std::filesystem::exists(mDir / "out.mtl"));
}

} // namespace
} // namespace ispm::test
