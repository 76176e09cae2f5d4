// GpuScene's light views at a new resolution (shadow_map_size, set or derived from a photon
// budget): the light cameras are re-made at it while the geometry and the BVH stay as uploaded.
#include "support/gl_fixture.h"

#include "render/gpu_scene.h"
#include "render/light_cameras.h"
#include "scene/scene_loader.h"

#include <string>

namespace ispm::test {
namespace {

class GpuSceneTest : public GlTest {};

TEST_F(GpuSceneTest, NewLightResolutionKeepsTheBvh) {
    const Scene model = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    constexpr int kBefore = 128;
    constexpr int kAfter = 512;
    GpuScene scene(model, kBefore);
    // The BVH's nodes as built: a rebuilt scene would hold them in a new allocation.
    const void* nodes = scene.getBvh().blasNodes.data();
    const size_t nodeCount = scene.getBvh().blasNodes.size();
    ASSERT_FALSE(scene.getLightCameras().empty());

    scene.setLightResolution(model, kAfter);
    EXPECT_EQ(scene.getLightResolution(), kAfter);
    EXPECT_EQ(scene.getBvh().blasNodes.data(), nodes);
    EXPECT_EQ(scene.getBvh().blasNodes.size(), nodeCount);
    // The views are those of the new resolution: their texels a quarter the size.
    const std::vector<LightCamera> expected = computeLightCameras(model, kAfter);
    const std::vector<LightCamera> before = computeLightCameras(model, kBefore);
    ASSERT_EQ(scene.getLightCameras().size(), expected.size());
    for (size_t v = 0; v < expected.size(); ++v) {
        EXPECT_FLOAT_EQ(scene.getLightCameras()[v].texelPerDepth, expected[v].texelPerDepth);
        EXPECT_NE(scene.getLightCameras()[v].texelPerDepth, before[v].texelPerDepth);
    }
}

} // namespace
} // namespace ispm::test
