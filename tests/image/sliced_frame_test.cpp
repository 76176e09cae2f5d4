// Frames drawn in slices (the viewer's beginFrame/continueFrame) against whole frames: the light
// views view by view, the trace and density passes and the raster splat in shares of the photons
// give the whole frame's image; a budget of zero runs one step per call, so the frame takes many
// calls; settings changed while a frame is in progress wait for the next one, and a rebuilt scene
// drops the frame in progress.
#include "support/gl_fixture.h"

#include "image/metrics.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <string>

namespace ispm::test {
namespace {

class SlicedFrameTest : public GlTest {};

constexpr int kSize = 64;

Settings makeSettings(const Scene& scene, const char* radiusMode) {
    Settings s = withSettings(scene.settings, {{"width", kSize},
                                               {"height", kSize},
                                               {"photons", 8000},
                                               {"shadow_map_size", 256},
                                               {"radius_mode", radiusMode}});
    return s;
}

// Runs `runner`'s next frame in slices of no time at all (one step per call); returns the calls.
int renderInSlices(FrameRunner& runner, double sliceMs) {
    runner.beginFrame(sliceMs);
    int calls = 1;
    while (!runner.continueFrame(0.0))
        ++calls;
    return calls;
}

// The photon passes' atomics store photons in another order each run, and the splat adds them
// in another order: float sums differ in their last bits (1e-8 relative seen, as for the
// gather). A slice that missed or doubled photons would differ by its share (1/16 or more).
constexpr double kMaxRelRmse = 1e-5;

TEST_F(SlicedFrameTest, SlicesGiveTheWholeFramesImage) {
    // A point light: six light views, one step each.
    for (const char* file : {"cornell.json", "courtyard.json"}) {
        for (const char* mode : {"density", "travel"}) {
            Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/" + file);
            const Settings settings = makeSettings(scene, mode);
            FrameRunner whole(scene, settings, gl::TimingMethod::CpuFinish);
            whole.renderFrame();
            FrameRunner sliced(scene, settings, gl::TimingMethod::CpuFinish);
            // Untimed passes start at 16 slices each: far more steps than passes.
            constexpr int kPasses = 16;
            const int calls = renderInSlices(sliced, 1.0);
            EXPECT_GT(calls, 3 * kPasses) << file << " " << mode;
            EXPECT_GT(sliced.getFrameInputs().splatDraws, 8u) << file << " " << mode;
            for (Aov aov : {Aov::Indirect, Aov::Total}) {
                const Image a = readTextureImage(whole.getAov(aov));
                const Image b = readTextureImage(sliced.getAov(aov));
                // computeRelRmse throws on a black reference: an image with no light fails.
                EXPECT_LT(computeRelRmse(b, a, 1), kMaxRelRmse) << file << " " << mode;
                EXPECT_NEAR(computeEnergyRatio(b, a), 1.0, kMaxRelRmse) << file << " " << mode;
            }
            // The passes' rows add their slices up: one row each, as a whole frame has.
            std::vector<std::string> names;
            for (const PassTiming& t : sliced.getTimings().passes)
                names.push_back(t.name);
            std::vector<std::string> wholeNames;
            for (const PassTiming& t : whole.getTimings().passes)
                wholeNames.push_back(t.name);
            EXPECT_EQ(names, wholeNames) << file << " " << mode;
        }
    }
}

TEST_F(SlicedFrameTest, SlicesFollowTheLastFramesPassTimes) {
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    FrameRunner runner(scene, makeSettings(scene, "density"), gl::TimingMethod::CpuFinish);
    runner.renderFrame(); // timed: the slices now follow the splat's time
    double splatMs = 0.0;
    for (const PassTiming& t : runner.getTimings().passes) {
        if (t.name == "splat") splatMs = t.ms;
    }
    ASSERT_GT(splatMs, 0.0);
    // Slices of a fifth of the splat: draws of half that, ten of them (rounding up).
    renderInSlices(runner, splatMs / 5.0);
    EXPECT_GE(runner.getFrameInputs().splatDraws, 9u);
    EXPECT_LE(runner.getFrameInputs().splatDraws, 11u);
    // A whole frame draws `splat_passes` draws.
    runner.renderFrame();
    EXPECT_EQ(runner.getFrameInputs().splatDraws, 1u);
}

TEST_F(SlicedFrameTest, EditsWaitForTheNextFrameAndARebuildDropsIt) {
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    const Settings settings = makeSettings(scene, "density");
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.beginFrame(1.0);
    ASSERT_FALSE(runner.continueFrame(0.0));
    Settings wider = withSettings(settings, {{"width", 2 * kSize}});
    runner.setSettings(wider);
    // The frame in progress keeps its size; the next frame's settings are the new ones.
    EXPECT_EQ(runner.getFrameSettings().width, kSize);
    EXPECT_EQ(runner.getSettings().getInt("width"), 2 * kSize);
    while (!runner.continueFrame(0.0)) {
    }
    EXPECT_EQ(runner.getFrameSettings().width, kSize);
    runner.beginFrame(1.0);
    EXPECT_EQ(runner.getFrameSettings().width, 2 * kSize);
    EXPECT_TRUE(runner.isFrameInProgress());
    // Lights added or removed: the frame in progress has the old ones and ends.
    runner.updateScene(SceneChange::AddedOrRemoved);
    EXPECT_FALSE(runner.isFrameInProgress());
    runner.renderFrame();
    const Image total = readTextureImage(runner.getAov(Aov::Total));
    EXPECT_EQ(total.width, 2 * kSize);
    float sum = 0.0f;
    for (const glm::vec3& p : total.pixels)
        sum += p.r + p.g + p.b;
    EXPECT_GT(sum, 0.0f);
}

} // namespace
} // namespace ispm::test
