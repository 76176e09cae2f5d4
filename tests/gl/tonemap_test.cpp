// The thesis's tone map (section 5.4.5) on saturated colours: the luminance (0.3 R + 0.6 G +
// 0.1 B) is mapped, clamped at luminance_max, and the colour scaled by mapped / original
// luminance before the gamma, so a saturated colour keeps its hue; a per-channel clamp and gamma
// would wash it out. The image is an emitting plane filling the view, nothing lit. Eye
// adaptation moves the derived white point towards each frame's in log luminance.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"

#include "render/frame.h"
#include "render/readback.h"
#include "support/test_settings.h"

#include <cmath>

namespace ispm::test {
namespace {

constexpr int kSize = 8;

// The display value of the middle pixel of a plane emitting `radiance`, with luminance_max 2 W/(m^2
// sr), gamma 2.2 and the operator `tonemap`.
glm::vec3 renderDisplay(glm::vec3 radiance, const char* tonemap) {
    Scene scene = makeLitPlane(0.0f, 0.0f, 1.0f, 100.0f); // black, unlit: emission alone
    scene.materials[0].emission = radiance;
    // The plane's winding faces down, away from the camera above it: it emits on both sides.
    scene.materials[0].emissionTwoSided = true;
    scene.camera.position = {0.0f, 1.0f, 0.01f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    Settings settings = makeTestSettings({{"width", kSize},
                                          {"height", kSize},
                                          {"bounces", 0},
                                          {"luminance_max", 2.0},
                                          {"gamma", 2.2},
                                          {"tonemap", tonemap}});
    FrameRunner runner(scene, settings, gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    const std::vector<glm::vec4> texels = readTextureTopDown(runner.getAov(Aov::Display));
    return glm::vec3(texels[(kSize / 2) * kSize + kSize / 2]);
}

glm::vec3 applyGamma(glm::vec3 c) {
    return glm::pow(c, glm::vec3(1.0f / 2.2f));
}

// 8-bit display values: half a step of rounding, and a little for the GPU's pow.
constexpr float kDisplayTolerance = 1.0f / 255.0f;

void expectNear(glm::vec3 actual, glm::vec3 expected) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(actual[i], expected[i], kDisplayTolerance) << "channel " << i;
}

class TonemapTest : public GlTest {};

TEST_F(TonemapTest, ThesisOperatorKeepsTheHueOfSaturatedColours) {
    // Luminance 0.44, under luminance_max 2: the colour is divided by 2 as it is, then gamma:
    // (0.73, 0.35, 0.35). Clamping and gamma-correcting each channel on its own gives
    // (1.00, 0.23, 0.23) for the same colour.
    const glm::vec3 red(1.0f, 0.2f, 0.2f);
    expectNear(renderDisplay(red, "thesis"), applyGamma(red / 2.0f));
    expectNear(renderDisplay(red, "thesis"), glm::vec3(0.730f, 0.351f, 0.351f));
    // Luminance 3.52, over luminance_max: mapped to 2, the colour scaled by 2 / 3.52 (red then
    // passes white and clips, green and blue keep their share of the luminance).
    const glm::vec3 bright(8.0f, 1.6f, 1.6f);
    const glm::vec3 scaled = bright * (2.0f / 3.52f) / 2.0f;
    expectNear(renderDisplay(bright, "thesis"), applyGamma(glm::min(scaled, glm::vec3(1.0f))));
    // Linear clips each channel: red at white, green and blue at 0.8 of it, hue lost.
    expectNear(renderDisplay(bright, "linear"),
               applyGamma(glm::min(bright / 2.0f, glm::vec3(1.0f))));
}

// Eye adaptation: the derived white point of a plane emitting `radiance` W/(m^2 sr) everywhere,
// rendered by `runner` after the plane's emission changed.
float renderWhite(FrameRunner& runner, Scene& scene, float radiance, double timeStepS) {
    scene.materials[0].emission = glm::vec3(radiance);
    scene.materials[0].emissionTwoSided = true; // seen from above, its back
    runner.updateScene(SceneChange::AddedOrRemoved);
    runner.setPresentation({.timeStepS = timeStepS});
    runner.renderFrame();
    return runner.getPasses().tonemap.readLuminanceMax();
}

Scene makeGlowingPlane() {
    Scene scene = makeLitPlane(0.0f, 0.0f, 1.0f, 100.0f);
    scene.camera.position = {0.0f, 1.0f, 0.01f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    return scene;
}

Settings makeAdaptationSettings(double timeConstantS) {
    Settings settings = makeTestSettings(
        {{"width", kSize}, {"height", kSize}, {"bounces", 0}, {"eye_adaptation_s", timeConstantS}});
    return settings;
}

TEST_F(TonemapTest, EyeAdaptationFollowsTheWhitePointInLogLuminance) {
    constexpr float kDim = 1.0f;
    constexpr float kBright = 16.0f;
    constexpr double kTimeConstantS = 1.0;
    constexpr double kStepS = 0.25;
    // The white points each image derives on its own (no adaptation): the histogram's bin edges
    // near 1 and 16.
    Scene still = makeGlowingPlane();
    FrameRunner instant(still, makeAdaptationSettings(0.0), gl::TimingMethod::CpuFinish);
    const float dimWhite = renderWhite(instant, still, kDim, kStepS);
    const float brightWhite = renderWhite(instant, still, kBright, kStepS);
    ASSERT_GT(brightWhite, 8.0f * dimWhite) << "the two images derive different white points";

    Scene scene = makeGlowingPlane();
    FrameRunner adapting(scene, makeAdaptationSettings(kTimeConstantS),
                         gl::TimingMethod::CpuFinish);
    // The first frame has no earlier white point: its own, whatever the step.
    EXPECT_EQ(renderWhite(adapting, scene, kDim, kStepS), dimWhite);
    // A quarter of the time constant after the light grew 16x: 1 - e^-0.25 = 22% of the way in
    // log luminance (float log2/exp2 on either side: 1e-4 relative).
    const double weight = 1.0 - std::exp(-kStepS / kTimeConstantS);
    const double expected = std::exp2(std::log2(double(dimWhite)) * (1.0 - weight) +
                                      std::log2(double(brightWhite)) * weight);
    const float white = renderWhite(adapting, scene, kBright, kStepS);
    EXPECT_NEAR(white, expected, 1e-4 * expected);
    // Ten time constants later it has arrived (e^-10 of the log ratio 4 is left: 0.02%).
    float settled = white;
    for (int i = 0; i < 40; ++i)
        settled = renderWhite(adapting, scene, kBright, kStepS);
    EXPECT_NEAR(settled, brightWhite, 1e-3 * double(brightWhite));
    // Adaptation off with time passing: each frame's own white point, exactly.
    EXPECT_EQ(renderWhite(instant, still, kDim, kStepS), dimWhite);
}

TEST(EyeAdaptation, WeightIsOneMinusTheExponentialOfTheStep) {
    EXPECT_EQ(computeAdaptationWeight(0.5, 0.0), 1.0);  // off: at once
    EXPECT_EQ(computeAdaptationWeight(-1.0, 2.0), 1.0); // no time step known: at once
    EXPECT_EQ(computeAdaptationWeight(0.0, 2.0), 0.0);  // no time passed: stays
    EXPECT_NEAR(computeAdaptationWeight(2.0, 2.0), 1.0 - std::exp(-1.0), 1e-15);
}

} // namespace
} // namespace ispm::test
