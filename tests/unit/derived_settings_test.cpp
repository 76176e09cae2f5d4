// Settings derived from the image's size when a scene does not set them: the light views'
// resolution follows the image below 129 px and stays at 1,024 from there on; a set value is
// kept whatever the size.
#include "scene/frame_settings.h"
#include "scene/settings.h"

#include <gtest/gtest.h>

namespace ispm::test {
namespace {

int deriveShadowMapSize(int width, int height) {
    Settings settings;
    settings.set("width", width, "test");
    settings.set("height", height, "test");
    return resolveFrameSettings(settings).shadowMapSize;
}

TEST(DerivedSettings, ShadowMapFollowsTheImageUpToItsFormerSize) {
    // 4 texels a pixel along the larger side, rounded up to a power of two.
    EXPECT_EQ(deriveShadowMapSize(128, 128), 512);
    EXPECT_EQ(deriveShadowMapSize(96, 40), 512);  // 384 -> 512: the larger side counts
    EXPECT_EQ(deriveShadowMapSize(40, 100), 512); // either axis
    EXPECT_EQ(deriveShadowMapSize(129, 64), 1024);
    // Small test images keep a usable light view; large ones the former fixed 1,024.
    EXPECT_EQ(deriveShadowMapSize(32, 32), 256);
    EXPECT_EQ(deriveShadowMapSize(64, 64), 256);
    EXPECT_EQ(deriveShadowMapSize(256, 256), 1024);
    EXPECT_EQ(deriveShadowMapSize(1280, 1024), 1024);
}

TEST(DerivedSettings, SetShadowMapIsKept) {
    Settings settings;
    settings.set("width", 64, "test");
    settings.set("height", 64, "test");
    settings.set("shadow_map_size", 2048, "test");
    EXPECT_EQ(resolveFrameSettings(settings).shadowMapSize, 2048);
    settings.set("width", 2000, "test");
    settings.set("shadow_map_size", 128, "test");
    EXPECT_EQ(resolveFrameSettings(settings).shadowMapSize, 128);
}

} // namespace
} // namespace ispm::test
