// The tiled gather (splat_mode gather) against the instanced splats: every pixel sums the photons
// of its tile with the splat's own kernel, normal and clip tests, so it gives the thesis's box
// splats' image (and, on the flat surfaces of these scenes, the flat squares') up to the order
// in which float sums add, with density radii and clip lines at walls, at full and at reduced
// splat resolution.
#include "support/gl_fixture.h"

#include "image/metrics.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <string>

namespace ispm::test {
namespace {

class SplatGatherTest : public GlTest {};

constexpr int kSize = 96;

Image renderIndirect(const std::string& file, const std::string& camera,
                     const std::string& resolution, const char* key, const char* value) {
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/" + file);
    selectCamera(scene, camera);
    Settings s = withSettings(
        scene.settings,
        {{"width", kSize}, {"height", kSize}, {"photons", 20000}, {"shadow_map_size", 512}});
    s.set("denoise", 0, "test"); // the splat buffer itself
    s.setEnum("splat_resolution", resolution, "test");
    s.setEnum(key, value, "test");
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    return readTextureImage(runner.getAov(Aov::Indirect));
}

// The photon passes' atomics store photons in another order each run, and the image adds their
// splats in another order: float sums differ in their last bits (1e-8 relative seen). A pixel
// missed or added by a tile's bounds would differ by a whole photon's share (1e-3 and more).
constexpr double kMaxRelRmse = 1e-5;

TEST_F(SplatGatherTest, GivesTheBoxSplatsImage) {
    struct View {
        const char* file;
        const char* camera;
        const char* resolution;
    };
    for (const View& v : {View{"cornell.json", "", "1"}, View{"courtyard.json", "room", "1"},
                          View{"cornell.json", "", "1/2"}}) {
        const Image box = renderIndirect(v.file, v.camera, v.resolution, "splat_shape", "box");
        const Image gather = renderIndirect(v.file, v.camera, v.resolution, "splat_mode", "gather");
        // computeEnergyRatio and computeRelRmse throw on a black reference: nothing to compare.
        EXPECT_LT(computeRelRmse(gather, box, 1), kMaxRelRmse)
            << v.file << " " << v.camera << " at " << v.resolution;
        EXPECT_NEAR(computeEnergyRatio(gather, box), 1.0, kMaxRelRmse) << v.file;
    }
}

} // namespace
} // namespace ispm::test
