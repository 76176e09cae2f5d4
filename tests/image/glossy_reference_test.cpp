// Glossy materials with the Fresnel split (shared/surface_brdf.h) through both reference
// estimators: camera paths choose lobes by the Fresnel weight of the direction they arrive from
// (the camera's side), light paths by the light's side, and both evaluate the same BRDF toward
// lights or the camera. They agree only if the BRDF is reciprocal and each sampler's weight is
// f cos / pdf, so agreement checks both.
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "image/metrics.h"
#include "scene/scene_loader.h"

namespace ispm::test {
namespace {

class GlossyReferenceTest : public GlTest {};

constexpr int kSize = 32; // px

TEST_F(GlossyReferenceTest, PathAndLightTracerAgreeOnAGlossyCornellBox) {
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    // Every surface glossy: a broad lobe (exponent 8) so that camera paths' next-event estimation
    // converges too, and a specular share that Fresnel raises toward grazing angles.
    constexpr float kSpecular = 0.15f;
    constexpr float kExponent = 8.0f;
    constexpr float kDiffuseKept = 0.8f; // diffuse + specular stays below 1
    for (Material& m : scene.materials) {
        m.diffuse *= kDiffuseKept;
        m.specular = glm::vec3(kSpecular);
        m.phongExponent = kExponent;
    }
    const Image light = renderReference(scene, "light", kSize, 256, 3);
    const Image path = renderReference(scene, "path", kSize, 64, 3);
    const ImageMetrics m = computeMetrics(light, path);
    std::printf("glossy cornell light vs path: energy %.4f rel RMSE 4x4 %.3f\n", m.energy,
                m.relRmse4);
    // Measured 1.0043 and 0.093. 2.5% on energy, as the diffuse Cornell box's test
    // (light_trace_test.cpp): a roulette with Fresnel beside a BRDF without it (the Phong BRDF
    // of before) measured 1.065 and fails. Subtler slips that keep each lobe's albedo (the
    // specular weight taking the arrival angle's Fresnel instead of the half vector's: 0.991;
    // the diffuse weight leaving out the outgoing direction's (1 - g): 1.018) stay inside it.
    EXPECT_NEAR(m.energy, 1.0, 0.025);
    EXPECT_LT(m.relRmse4, 0.15);
}

} // namespace
} // namespace ispm::test
