// Animated scenes through the whole frame: after Scene::update + FrameRunner::updateScene the
// rasterised passes, the shadow maps and the photon tracer's BVH all see the moved scene.
#include "support/gl_fixture.h"

#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace ispm::test {
namespace {

class AnimationRenderTest : public GlTest {};

Settings makeSettings(int width, int height, int photons, int bounces) {
    Settings s = makeTestSettings(
        {{"width", width}, {"height", height}, {"photons", photons}, {"bounces", bounces}});
    s.set("shadow_map_size", 256, "test"); // small: the tests look at shadows metres wide
    return s;
}

Image renderAt(Scene& scene, FrameRunner& runner, double timeS, Aov aov) {
    scene.update(timeS);
    runner.updateScene();
    runner.renderFrame();
    return readTextureImage(runner.getAov(aov));
}

// The pixel where world point `pW` is seen (row 0 at the top, as images read back).
glm::ivec2 projectToPixel(const Camera& camera, const glm::vec3& pW, int width, int height) {
    // x and y after the divide do not depend on the clip planes: any valid pair does.
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::vec4 clip = computeClipFromView(camera, aspect, 0.1f, 100.0f) *
                           computeViewFromWorld(camera) * glm::vec4(pW, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {static_cast<int>((ndc.x * 0.5f + 0.5f) * static_cast<float>(width)),
            static_cast<int>((0.5f - ndc.y * 0.5f) * static_cast<float>(height))};
}

float getLuminance(const Image& image, const glm::ivec2& px) {
    return glm::dot(image.at(px.x, px.y), glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

TEST_F(AnimationRenderTest, DynamicSceneMovesBetweenTimes) {
    constexpr int kWidth = 96;
    constexpr int kHeight = 72;
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/dynamic.json");
    FrameRunner runner(scene, makeSettings(kWidth, kHeight, 3000, 1), gl::TimingMethod::CpuFinish);
    const Image start = renderAt(scene, runner, 0.0, Aov::Direct);
    const Image later = renderAt(scene, runner, 3.0, Aov::Direct);
    const Image again = renderAt(scene, runner, 0.0, Aov::Direct);

    // Same time, same image: the update is a function of t alone (direct light has no noise).
    int changed = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            EXPECT_EQ(start.at(x, y), again.at(x, y)) << x << "," << y;
            constexpr float kChangedRelative = 0.05f;
            const float a = getLuminance(start, {x, y});
            const float b = getLuminance(later, {x, y});
            changed += std::abs(a - b) > kChangedRelative * std::max(a, b) ? 1 : 0;
        }
    }
    // Objects, the sun's shadows and the spot's pool all moved, but the pavilion stayed.
    const int pixels = kWidth * kHeight;
    EXPECT_GT(changed, pixels / 20) << changed;
    EXPECT_LT(changed, pixels * 9 / 10) << changed;

    // The red box orbits a quarter turn in 3 s (period 12 s): from +x to -z (towards the camera).
    const glm::vec3 boxAtStartW{3.5f, 0.3f, 0.0f};
    const glm::vec3 boxLaterW{0.0f, 0.3f, -3.5f};
    for (const glm::vec3& p : {boxAtStartW, boxLaterW}) {
        const glm::ivec2 px = projectToPixel(scene.camera, p, kWidth, kHeight);
        const glm::vec3 a = start.at(px.x, px.y);
        const glm::vec3 b = later.at(px.x, px.y);
        EXPECT_GT(glm::length(a - b), 0.05f * std::max(glm::length(a), glm::length(b)))
            << px.x << "," << px.y;
    }
}

// A sun straight down the slope (0, -1, 1) and a block floating 1 m up, sliding +2 m in x in 1 s:
// its shadow on the floor, 1.2 m further in z, must slide with it.
TEST_F(AnimationRenderTest, ShadowFollowsMovingBlock) {
    constexpr int kSize = 64;
    const nlohmann::json doc = nlohmann::json::parse(R"({
        "camera": {"position": [0, 6, 6], "target": [0, 0, 0.5]},
        "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
        "objects": [
            {"type": "box", "material": "grey", "min": [-4, -0.1, -4], "max": [4, 0, 4]},
            {"type": "box", "material": "grey", "min": [-1.3, 1, -0.3], "max": [-0.7, 1.5, 0.3],
             "animation": {"translate_per_s": [2, 0, 0]}}
        ],
        "lights": [{"type": "sun", "direction": [0, -1, 1], "irradiance": [10, 10, 10]}]
    })");
    Scene scene = parseScene(doc, "shadow.json", ".");
    FrameRunner runner(scene, makeSettings(kSize, kSize, 0, 0), gl::TimingMethod::CpuFinish);
    const Image start = renderAt(scene, runner, 0.0, Aov::Direct);
    const Image later = renderAt(scene, runner, 1.0, Aov::Direct);

    // Lit floor: rho E cos / pi with cos 45 degrees.
    const float litRadiance = 0.5f * 10.0f * 0.70710678f / 3.14159265f;
    const glm::ivec2 left = projectToPixel(scene.camera, {-1.0f, 0.0f, 1.2f}, kSize, kSize);
    const glm::ivec2 right = projectToPixel(scene.camera, {1.0f, 0.0f, 1.2f}, kSize, kSize);
    EXPECT_LT(getLuminance(start, left), 0.1f * litRadiance);
    EXPECT_NEAR(getLuminance(start, right), litRadiance, 0.05f * litRadiance);
    EXPECT_NEAR(getLuminance(later, left), litRadiance, 0.05f * litRadiance);
    EXPECT_LT(getLuminance(later, right), 0.1f * litRadiance);
}

// A spot 1 m over a floor, pointing down; a lid out of the spot's view (behind it) rises from
// under the floor to above the spot. The light's G-buffer never sees the lid, so only the
// tracer's BVH can: with the lid below, photons leaving the floor escape; above, they land on it.
TEST_F(AnimationRenderTest, PhotonTraceUsesTheMovedBvh) {
    const nlohmann::json doc = nlohmann::json::parse(R"({
        "camera": {"position": [0, 1.5, -2.5], "target": [0, 0, 0]},
        "materials": {"white": {"diffuse": [0.8, 0.8, 0.8]}},
        "objects": [
            {"type": "box", "material": "white", "min": [-3, -0.1, -3], "max": [3, 0, 3]},
            {"type": "box", "name": "lid", "material": "white", "min": [-3, 0, -3],
             "max": [3, 0.1, 3], "translate": [0, -3, 0],
             "animation": {"translate_per_s": [0, 5, 0]}}
        ],
        "lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0],
                    "intensity": [10, 10, 10], "inner_deg": 20, "outer_deg": 30}]
    })");
    Scene scene = parseScene(doc, "lid.json", ".");
    FrameRunner runner(scene, makeSettings(32, 32, 4000, 1), gl::TimingMethod::CpuFinish);
    runner.renderFrame();
    const PhotonCounts below = readPhotonCounts(runner);
    scene.update(1.0); // the lid at y = 2
    runner.updateScene();
    runner.renderFrame();
    const PhotonCounts above = readPhotonCounts(runner);

    ASSERT_GT(below.bounced, 0u);
    EXPECT_EQ(below.stored, 0u); // nothing above the floor to land on
    // Half the floor's diffuse bounces at least leave within the lid's solid angle.
    EXPECT_GT(above.stored, above.bounced / 2) << above.stored << " of " << above.bounced;
}

} // namespace
} // namespace ispm::test
