// frame_ms_target in a running FrameRunner: a target no frame can meet takes the budget down to
// its floor in 2x steps, a target far above the frame takes it up, and a still view that
// accumulates keeps its budget; timer queries read after every frame (bench) set it too. The
// budget is the frame's photon count, not a setting: the settings stay as set, and with shadows
// ray the light views follow it (their derived size) while the BVH stays.
#include "support/gl_fixture.h"

#include "render/frame.h"
#include "render/frame_budget.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <string>

namespace ispm::test {
namespace {

Settings makeSettings(const Scene& scene, double targetMs, int accumulate) {
    Settings s = withSettings(scene.settings, {{"width", 32},
                                               {"height", 32},
                                               {"photons", 8000},
                                               {"bounces", 1},
                                               {"shadow_map_size", 128},
                                               {"frame_ms_target", targetMs},
                                               {"accumulate", accumulate}});
    return s;
}

class FrameBudgetTest : public GlTest {};

TEST_F(FrameBudgetTest, BudgetFollowsTheTarget) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    {
        // 1 us a frame: 8000 -> 4000 -> 2000 -> 1000, three frames measured at each budget.
        FrameRunner runner(scene, makeSettings(scene, 1e-3, 0), gl::TimingMethod::CpuFinish);
        for (int f = 0; f < 3; ++f)
            runner.renderFrame();
        EXPECT_EQ(runner.getFrameSettings().photons, 4000);
        for (int f = 0; f < 9; ++f)
            runner.renderFrame();
        EXPECT_EQ(runner.getFrameSettings().photons, kMinAdaptedPhotons);
    }
    {
        // 1,000 s a frame: the budget doubles every three frames.
        FrameRunner runner(scene, makeSettings(scene, 1e6, 0), gl::TimingMethod::CpuFinish);
        for (int f = 0; f < 6; ++f)
            runner.renderFrame();
        EXPECT_EQ(runner.getFrameSettings().photons, 32000);
    }
    {
        // A still view accumulating: its frames converge, the budget stays.
        FrameRunner runner(scene, makeSettings(scene, 1e-3, 16), gl::TimingMethod::CpuFinish);
        for (int f = 0; f < 9; ++f)
            runner.renderFrame();
        EXPECT_EQ(runner.getFrameSettings().photons, 8000);
    }
}

TEST_F(FrameBudgetTest, BudgetMovesTheDerivedLightViewsNotTheBvh) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    Settings s = scene.settings; // shadow_map_size derived
    s = withSettings(s, {{"width", 32},
                         {"height", 32},
                         {"photons", 8000},
                         {"bounces", 1},
                         {"frame_ms_target", 1e6},
                         {"shadows", "ray"}});
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    // 8,000 photons: twice sqrt(photons) texels a side, 256 at least.
    EXPECT_EQ(runner.getPasses().scene.getLightResolution(), 256);
    const void* nodes = runner.getPasses().scene.getBvh().blasNodes.data();
    for (int f = 0; f < 6; ++f)
        runner.renderFrame();
    // 8,000 -> 16,000 -> 32,000 photons: 358 texels, rounded up to 512.
    const FrameSettings& frame = runner.getFrameSettings();
    EXPECT_EQ(frame.photons, 32000);
    EXPECT_EQ(frame.shadowMapSize, 512);
    EXPECT_EQ(frame.splatNeighbours, computeSplatNeighbours(s, 32000));
    EXPECT_EQ(runner.getSettings().getInt("photons"), 8000); // as set
    EXPECT_EQ(runner.getPasses().scene.getLightResolution(), 512);
    EXPECT_EQ(runner.getPasses().scene.getBvh().blasNodes.data(), nodes);
    EXPECT_EQ(runner.getPasses().lightViews.getGBuffer().getWidth(), 512);
}

TEST_F(FrameBudgetTest, TimerQueriesReadAfterEveryFrameStillSetTheBudget) {
    // bench and render wait for each frame's timer queries (waitForTimings) as soon as it is
    // drawn, before the frame after it looks for finished ones: the budget must follow them.
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    FrameRunner runner(scene, makeSettings(scene, 1e6, 0), gl::TimingMethod::TimerQuery);
    for (int f = 0; f < 3; ++f) {
        runner.renderFrame();
        runner.waitForTimings();
    }
    EXPECT_EQ(runner.getFrameSettings().photons, 16000);
}

} // namespace
} // namespace ispm::test
