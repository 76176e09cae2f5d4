// A scene's size does not change its image: the Cornell box scaled by 1e-6 (the smallest scale
// the format accepts) and by 1e4, with its spot's intensity scaled by the square (the same
// irradiance at the scaled distances), renders the picture of the metre-sized box. Ray offsets,
// clip planes, the sun's footprint and the light's distance floor all follow the scene's size;
// offsets fixed in metres lost the indirect light at 1e-4 and blackened the image at 1e-6.
#include "support/gl_fixture.h"
#include "support/render_support.h"

#include "image/metrics.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "support/test_settings.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ispm::test {
namespace {

class SceneScaleTest : public GlTest {};

constexpr int kSize = 64;

Settings makeSettings(const Scene& scene) {
    Settings s = withSettings(
        scene.settings,
        {{"width", kSize}, {"height", kSize}, {"photons", 20000}, {"shadow_map_size", 512}});
    return s;
}

Image renderScaled(float k, Aov aov) {
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(k));
    for (Instance& instance : scene.instances)
        instance.worldFromObject = scale * instance.worldFromObject;
    scene.camera.position *= k;
    scene.camera.target *= k;
    for (Light& light : scene.lights) {
        light.position *= k;
        light.intensity *= k * k;
    }
    return renderAov(scene, makeSettings(scene), aov);
}

TEST_F(SceneScaleTest, TheCornellBoxLooksTheSameAtAnySize) {
    for (Aov aov : {Aov::Direct, Aov::Indirect}) {
        const Image metre = renderScaled(1.0f, aov);
        for (float k : {1e-6f, 1e4f}) {
            const Image scaled = renderScaled(k, aov);
            // The same photons take the same paths; float round-off at other magnitudes moves a
            // few of them across a texel or a cell (0.1-0.2% seen at 4x4). A lost bounce or a
            // clipped view misses by tens of percent.
            EXPECT_NEAR(computeEnergyRatio(scaled, metre), 1.0, 0.01) << "scale " << k;
            EXPECT_LT(computeRelRmse(scaled, metre, 4), 0.02)
                << "scale " << k << " aov " << int(aov);
        }
    }
}

TEST_F(SceneScaleTest, AHugeDistantObjectLeavesTheRoomAsItWas) {
    // A 1e6 m block 5e6 m from the Cornell box: the derived near planes and the ray offsets once
    // followed the whole scene's size (700 m and 70 m), which blackened the box and let every
    // photon leave it, and the derived splat radii its whole area (density cells ~1 km wide,
    // discs clamped at ~7e4 m: no indirect light). The block is out of view: the radii follow
    // the area in view (GpuScene::getSurfaceArea), as without it.
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    const Scene plain = scene;
    Mesh block;
    block.name = "block";
    for (int i = 0; i < 8; ++i) {
        block.positions.push_back(
            glm::vec3((i & 1) ? 5e6f : 4e6f, (i & 2) ? 1e5f : -1e5f, (i & 4) ? 5e6f : 4e6f));
    }
    block.triangles = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}};
    block.triangleMaterials = {0, 0, 0, 0};
    scene.instances.push_back({static_cast<uint32_t>(scene.meshes.size()), glm::mat4(1.0f)});
    scene.meshes.push_back(std::move(block));
    const auto render = [](const Scene& s, Aov aov) { return renderAov(s, makeSettings(s), aov); };
    for (Aov aov : {Aov::Direct, Aov::Indirect}) {
        const Image expected = render(plain, aov);
        const Image actual = render(scene, aov);
        // The block takes a share of the spot's photons and of the light cameras' depth range:
        // 5% of the energy; lost photons or a clipped room miss by 100%.
        EXPECT_NEAR(computeEnergyRatio(actual, expected), 1.0, 0.05) << int(aov);
        EXPECT_LT(computeRelRmse(actual, expected, 4), 0.1) << int(aov);
    }
}

} // namespace
} // namespace ispm::test
