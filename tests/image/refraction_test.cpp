// Radiance across refraction in the reference path tracer: a camera inside glass sees the world
// outside brighter by ior^2 (L / n^2 is what a ray carries unchanged), times the face's Fresnel
// transmittance. The oracle refracts each pixel's ray by Snell's law and takes the exact Fresnel
// term written out here.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"

#include "render/reference_pass.h"
#include "scene/mesh_builder.h"
#include "support/test_settings.h"

#include <cmath>

namespace ispm::test {
namespace {

class RefractionTest : public GlTest {};

constexpr int kSize = 32;    // px
constexpr int kBlockPx = 8;  // compared on block means: the Fresnel choice is a coin per sample
constexpr double kIor = 1.5; // the glass
constexpr float kRho = 0.5f; // the floor
constexpr float kIntensity = 10.0f; // W/sr
constexpr float kLightHeightM = 0.3f;
constexpr double kGlassBottomM = 0.5; // the glass box's lower face, between light and camera

// Unpolarised Fresnel reflectance leaving a medium of index n into air at cos(incidence) c.
double computeExitFresnel(double c, double n) {
    const double sin2T = n * n * (1.0 - c * c);
    const double cosT = std::sqrt(1.0 - sin2T);
    const double rs = (n * c - cosT) / (n * c + cosT);
    const double rp = (c - n * cosT) / (c + n * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

TEST_F(RefractionTest, CameraInsideGlassSeesIorSquaredTimesTheTransmittedRadiance) {
    Scene scene = makeLitPlane(kRho, kIntensity, kLightHeightM, 10.0f);
    Material glass;
    glass.name = "glass";
    glass.transmissive = glm::vec3(1.0f);
    glass.ior = float(kIor);
    const auto glassIndex = static_cast<uint32_t>(scene.materials.size());
    scene.materials.push_back(glass);
    appendBox(scene.meshes[0], {-3.0f, float(kGlassBottomM), -3.0f}, {3.0f, 3.0f, 3.0f},
              glassIndex);
    scene.camera.position = {0.1f, 2.0f, 0.05f};
    scene.camera.target = {0.1f, 0.0f, 0.05f};
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.fovYDeg = 30.0f;
    Settings settings = makeTestSettings({{"width", kSize}, {"height", kSize}});
    // One reflection: through the glass face to the floor, which sees the light. Light that
    // the face reflects back into the glass is bounce 2 and more.
    settings.set("bounces", 1, "test");
    constexpr int kSpp = 256;
    ReferencePass reference(scene, settings);
    for (int s = 0; s < kSpp; ++s)
        reference.addSample();
    const Image image = reference.readMean();

    const glm::dvec3 eye(scene.camera.position);
    double sumImage = 0.0;
    double sumExpected = 0.0;
    for (int by = 0; by < kSize; by += kBlockPx) {
        for (int bx = 0; bx < kSize; bx += kBlockPx) {
            double block = 0.0;
            double expected = 0.0;
            for (int y = by; y < by + kBlockPx; ++y) {
                for (int x = bx; x < bx + kBlockPx; ++x) {
                    block += double(image.at(x, y).x);
                    // The pixel's ray, its exit point on the glass face and Snell's law there.
                    const glm::dvec3 d = glm::normalize(
                        projectToGround(scene, kSize, kSize, x + 0.5, y + 0.5) - eye);
                    const glm::dvec3 q = eye + d * ((eye.y - kGlassBottomM) / -d.y);
                    const double cosI = -d.y; // the face's normal toward the eye is +y
                    const double sin2T = kIor * kIor * (1.0 - cosI * cosI);
                    const glm::dvec3 t =
                        kIor * d + glm::dvec3(0.0, kIor * cosI - std::sqrt(1.0 - sin2T), 0.0);
                    const glm::dvec3 p = q + t * (q.y / -t.y);
                    expected += kIor * kIor * (1.0 - computeExitFresnel(cosI, kIor)) *
                                computePlaneRadiance(kRho, kIntensity, kLightHeightM, p);
                }
            }
            // 2%: 64 pixels x 256 samples average the Fresnel coin (relative sigma ~0.2 per
            // sample) to ~0.2%; box-filtered pixels against centred rays add ~0.5%.
            EXPECT_NEAR(block / expected, 1.0, 0.02) << "block " << bx << "," << by;
            sumImage += block;
            sumExpected += expected;
        }
    }
    std::printf("camera in glass: mean ratio %.4f\n", sumImage / sumExpected);
    // Without the ior^2 the ratio is 1 / 2.25; with it inverted 1 / 5.06.
    EXPECT_NEAR(sumImage / sumExpected, 1.0, 0.01);
}

} // namespace
} // namespace ispm::test
