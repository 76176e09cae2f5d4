// `rng` (FrameRunner, photon_trace.comp): which numbers scatter a photon from one frame to the
// next. fixed and object_space repeat a still frame exactly, per_frame draws new photons every
// frame, and object_space's numbers (keyed on the hit point in its triangle) are not fixed's
// (keyed on the photon's emission cell).
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ispm::test {
namespace {

constexpr int kSize = 48; // px: small, the photons still light every wall

// Two consecutive frames' indirect light of the Cornell box with `rng` = mode.
std::pair<Image, Image> renderTwoFrames(const std::string& mode) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    Settings s = withSettings(scene.settings, {{"width", kSize},
                                               {"height", kSize},
                                               {"photons", 4000},
                                               {"bounces", 3},
                                               {"shadow_map_size", 256},
                                               {"rng", mode}});
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    Image first = readTextureImage(runner.getAov(Aov::Indirect));
    runner.renderFrame();
    return {std::move(first), readTextureImage(runner.getAov(Aov::Indirect))};
}

class RngModesTest : public GlTest {};

TEST_F(RngModesTest, StillFramesRepeatOrRedrawAsTheModeSays) {
    const auto [fixed1, fixed2] = renderTwoFrames("fixed");
    const auto [perFrame1, perFrame2] = renderTwoFrames("per_frame");
    const auto [object1, object2] = renderTwoFrames("object_space");
    // The same photons on the same paths (only the GPU's order of atomic appends and float sums
    // may differ).
    EXPECT_LT(computeMaxRelativeDifference(fixed2, fixed1), 1e-4);
    EXPECT_LT(computeMaxRelativeDifference(object2, object1), 1e-4);
    // New photons: one frame's noise apart (blotches of 4,000 photons at 48 px).
    EXPECT_GT(computeMaxRelativeDifference(perFrame2, perFrame1), 0.05);
    // The first frame of per_frame is fixed's (seed + 0); object_space scatters after the first
    // hit by other numbers than fixed.
    EXPECT_LT(computeMaxRelativeDifference(perFrame1, fixed1), 1e-4);
    EXPECT_GT(computeMaxRelativeDifference(object1, fixed1), 0.05);
}

TEST_F(RngModesTest, ImportanceMapsStayWhileOnlyObjectsMove) {
    // The moving cube's room: an object moving keeps the maps that aim the photons (so first hits
    // and, with fixed or object_space numbers, whole paths stay where nothing moved); a camera
    // move rebuilds them.
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/moving_cube.json");
    Settings s = withSettings(
        scene.settings,
        {{"width", kSize}, {"height", kSize}, {"photons", 4000}, {"shadow_map_size", 256}});
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    auto readMaps = [&runner] {
        const gl::Buffer& cdf = runner.getPasses().importance.getCdf();
        return cdf.read<float>(cdf.getSize() / sizeof(float));
    };
    runner.renderFrame();
    const std::vector<float> first = readMaps();
    ASSERT_FALSE(scene.instances.empty());
    scene.instances.back().worldFromObject =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.0f, 0.0f)) *
        scene.instances.back().worldFromObject;
    runner.updateScene();
    runner.renderFrame();
    EXPECT_EQ(readMaps(), first) << "an object moved: the maps must stay";
    scene.camera.position += glm::vec3(0.2f, 0.0f, 0.0f);
    runner.renderFrame();
    EXPECT_NE(readMaps(), first) << "the camera moved: the maps must follow";
}

} // namespace
} // namespace ispm::test
