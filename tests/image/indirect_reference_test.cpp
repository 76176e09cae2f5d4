// ispm's indirect light against the reference path tracer's (reference(B) - reference(0)) on the
// Cornell box: an error bound measured here, and proof that the bound catches indirect light that
// is doubled, halved or missing.
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "image/metrics.h"
#include "render/reference_pass.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

namespace ispm::test {
namespace {

class IndirectReferenceTest : public GlTest {};

Image scaleImage(Image image, float s) {
    for (glm::vec3& p : image.pixels)
        p *= s;
    return image;
}

TEST_F(IndirectReferenceTest, CornellIndirectWithinMeasuredBound) {
    constexpr int kSize = 48;
    constexpr int kBounces = 2;
    constexpr int kReferenceSpp = 96;
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    Settings settings = withSettings(scene.settings, {{"width", kSize},
                                                      {"height", kSize},
                                                      {"bounces", kBounces},
                                                      {"photons", 50000},
                                                      {"shadow_map_size", 512}});

    const Image referenceIndirect = renderReferenceIndirect(scene, settings, kReferenceSpp);
    const Image indirect = renderAov(scene, settings, Aov::Indirect);

    const double ispm = computeRelMse(indirect, referenceIndirect, nullptr, kRelMseEpsilon);
    const double doubled =
        computeRelMse(scaleImage(indirect, 2.0f), referenceIndirect, nullptr, kRelMseEpsilon);
    const double halved =
        computeRelMse(scaleImage(indirect, 0.5f), referenceIndirect, nullptr, kRelMseEpsilon);
    const double missing =
        computeRelMse(scaleImage(indirect, 0.0f), referenceIndirect, nullptr, kRelMseEpsilon);
    const glm::dvec3 ratio = computeMeanRatio(indirect, referenceIndirect, nullptr);
    std::printf("indirect relMSE: ispm %.4f, doubled %.4f, halved %.4f, missing %.4f; mean ratio "
                "%.3f %.3f %.3f\n",
                ispm, doubled, halved, missing, ratio.x, ratio.y, ratio.z);

    // The bound, measured over seeds 1-4 at these settings: ispm scores 0.054-0.059 (splat blur,
    // photon noise and the reference's own noise at 96 spp); halving the indirect light scores
    // 0.108-0.114, dropping it 0.356-0.361, doubling it 0.49-0.55. 0.08 sits between the groups.
    constexpr double kMaxRelMse = 0.08;
    EXPECT_LT(ispm, kMaxRelMse);
    EXPECT_GT(doubled, kMaxRelMse);
    EXPECT_GT(halved, kMaxRelMse);
    EXPECT_GT(missing, kMaxRelMse);
    // The energy itself: splats lose what falls past edges and corners, which keeps ispm a few
    // percent low (measured 0.93-0.97 over seeds 1-4); 15% covers it and fails on a wrong factor.
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(ratio[c], 1.0, 0.15) << "channel " << c;
}

} // namespace
} // namespace ispm::test
