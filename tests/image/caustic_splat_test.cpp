// Caustics keep their shape through the splat buffer's resolution and the filter: in radius_mode
// density the photons that glass or a mirror focused are splatted apart, at the image's
// resolution and unfiltered (SplatPass, kSplatCausticPhotons), so the caustics scene's focus
// under the glass sphere is the same at splat_resolution 1/2 with the filter on as at full
// resolution without it. Drawn with the diffuse light, the half-resolution buffer and the a-trous
// filter smeared the focus (a few pixels wide) into a blob several times its size.
#include "support/gl_fixture.h"

#include "image/metrics.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace ispm::test {
namespace {

constexpr int kSize = 128; // px: the sphere's focus spans a few pixels, its shadow ~25

struct CausticsFrame {
    Image indirect;
    Image normal; // the viewer G-buffer's, row 0 at the top like indirect
};

CausticsFrame renderCaustics(const std::string& resolution, int denoise) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/caustics.json");
    Settings s = withSettings(scene.settings, {{"width", kSize}, {"height", kSize}});
    s.set("specular_depth", 0, "test"); // the splats' light alone
    s = withSettings(s, {{"denoise", denoise}, {"splat_resolution", resolution}});
    FrameRunner runner(scene, s, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    return {readTextureImage(runner.getAov(Aov::Indirect)),
            readTextureImage(runner.getPasses().gbuffer.getGBuffer().getChannel("normal"))};
}

float sumChannels(const glm::vec3& c) {
    return c.x + c.y + c.z;
}

// The caustics on the floor (normal up): pixels with over 4x the floor's mean indirect light,
// the focus under the sphere and its bright ring. (The glossy panel's light, photons on a narrow
// lobe, is splatted with the diffuse photons and filtered: it is left out.)
PixelMask selectFloorCaustic(const CausticsFrame& frame) {
    const Image& image = frame.indirect;
    const auto isFloor = [&](int x, int y) { return frame.normal.at(x, y).y > 0.9f; };
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (!isFloor(x, y)) continue;
            sum += double(sumChannels(image.at(x, y)));
            ++count;
        }
    }
    EXPECT_GT(sum, 0.0) << "the floor holds indirect light";
    const double threshold = count > 0 ? 4.0 * sum / count : 0.0;
    PixelMask mask(size_t(image.width * image.height), 0);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            mask[size_t(y * image.width + x)] =
                isFloor(x, y) && double(sumChannels(image.at(x, y))) > threshold ? 1 : 0;
        }
    }
    return mask;
}

class CausticSplatTest : public GlTest {};

TEST_F(CausticSplatTest, CausticsKeepTheirShapeAtHalfResolutionAndThroughTheFilter) {
    // The same photons (seed, budget and importance maps do not depend on the splat buffer).
    const CausticsFrame sharpFrame = renderCaustics("1", 0);
    const Image& sharp = sharpFrame.indirect;
    const Image filtered = renderCaustics("1/2", 2).indirect;
    const PixelMask caustic = selectFloorCaustic(sharpFrame);
    const auto pixels = std::count(caustic.begin(), caustic.end(), uint8_t(1));
    std::printf("caustic: %td pixels\n", pixels);
    ASSERT_GT(pixels, 20) << "the sphere focuses the spot onto the floor";
    const double energy = computeEnergyRatio(filtered, sharp, &caustic);
    const double relRmse = computeRelRmse(filtered, sharp, kRelRmseBlock, &caustic);
    std::printf("caustic at 1/2 and filtered against full resolution, unfiltered: energy %.3f, "
                "rel RMSE (4x4) %.3f\n",
                energy, relRmse);
    // Only the diffuse light under the caustic is filtered and upsampled, a small part of it.
    EXPECT_NEAR(energy, 1.0, 0.02);
    EXPECT_LT(relRmse, 0.02);
}

} // namespace
} // namespace ispm::test
