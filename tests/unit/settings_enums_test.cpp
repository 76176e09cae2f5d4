// The enumerated settings' choices, in table order, are the uint constants the shaders compare
// against (shared/*.h): a choice added or moved in one place and not the other fails here.
#include "settings/frame_settings.h"
#include "settings/settings.h"
#include "support/test_settings.h"

#include <shared/light_trace_data.h>
#include <shared/photon_data.h>
#include <shared/photon_scatter.h>
#include <shared/scene_data.h>

#include <gtest/gtest.h>

#include <string_view>
#include <utility>
#include <vector>

namespace ispm::test {
namespace {

void expectChoices(std::string_view setting,
                   const std::vector<std::pair<std::string_view, uint32_t>>& expected) {
    const SettingDesc* desc = findSetting(setting);
    ASSERT_NE(desc, nullptr) << setting;
    ASSERT_EQ(desc->choices.size(), expected.size()) << setting;
    for (const auto& [name, index] : expected) {
        ASSERT_LT(index, desc->choices.size()) << setting << " " << name;
        EXPECT_EQ(desc->choices[index], name) << setting;
    }
}

TEST(SettingsEnums, ChoicesMatchTheShaderConstants) {
    expectChoices("radius_mode", {{"travel", gpu::kRadiusTravel},
                                  {"path_density", gpu::kRadiusPathDensity},
                                  {"density", gpu::kRadiusDensity}});
    expectChoices("rng_generator",
                  {{"pcg", gpu::kRngPcg}, {"lcg", gpu::kRngLcg}, {"sobol", gpu::kRngSobol}});
    expectChoices("rng", {{"fixed", gpu::kRngFixed},
                          {"per_frame", gpu::kRngPerFrame},
                          {"object_space", gpu::kRngObjectSpace}});
    expectChoices("reference_method",
                  {{"path", gpu::kReferencePath}, {"light", gpu::kReferenceLight}});
    expectChoices("tonemap", {{"thesis", gpu::kTonemapThesis},
                              {"filmic", gpu::kTonemapFilmic},
                              {"linear", gpu::kTonemapLinear}});
}

// splat_clip auto clips the density radii's discs and draws the travel modes' whole (the thesis's,
// and cheaper: no box query per photon); on and off hold for every radius mode.
TEST(SettingsEnums, SplatClipFollowsTheRadiusModeUnlessSet) {
    const auto resolve = [](std::string_view mode, std::string_view clip) {
        Settings s = makeTestSettings({{"radius_mode", mode}, {"splat_clip", clip}});
        return resolveFrameSettings(s).splatClip;
    };
    EXPECT_TRUE(resolve("density", "auto"));
    EXPECT_FALSE(resolve("travel", "auto"));
    EXPECT_FALSE(resolve("path_density", "auto"));
    for (std::string_view mode : {"travel", "path_density", "density"}) {
        EXPECT_TRUE(resolve(mode, "on")) << mode;
        EXPECT_FALSE(resolve(mode, "off")) << mode;
    }
}

// surface_ends auto measures the density radii's discs and leaves the travel modes' whole; clip
// lines renormalise per pixel instead, so with splat_clip on it never applies.
TEST(SettingsEnums, SurfaceEndsAppliesOnlyWithoutClipLines) {
    const auto resolve = [](std::string_view mode, std::string_view clip, std::string_view ends) {
        Settings s =
            makeTestSettings({{"radius_mode", mode}, {"splat_clip", clip}, {"surface_ends", ends}});
        return resolveFrameSettings(s).surfaceEnds;
    };
    EXPECT_TRUE(resolve("density", "off", "auto"));
    EXPECT_FALSE(resolve("travel", "off", "auto"));
    EXPECT_FALSE(resolve("path_density", "off", "auto"));
    for (std::string_view mode : {"travel", "path_density", "density"}) {
        EXPECT_TRUE(resolve(mode, "off", "on")) << mode;
        EXPECT_FALSE(resolve(mode, "off", "off")) << mode;
        for (std::string_view ends : {"auto", "on", "off"})
            EXPECT_FALSE(resolve(mode, "on", ends)) << mode << " " << ends;
    }
    // The default: density radii with clip lines.
    EXPECT_FALSE(resolveFrameSettings(Settings()).surfaceEnds);
}

// widen_strong widens travel and path-density discs; the density radii (the default) spread
// strong photons by their neighbours already, so it resolves off there.
TEST(SettingsEnums, WidenStrongIsOffUnlessSetForTravelRadii) {
    Settings s = makeTestSettings({{"radius_mode", "travel"}});
    EXPECT_FALSE(resolveFrameSettings(s).widenStrong);
    s.setEnum("widen_strong", "on", "test");
    EXPECT_TRUE(resolveFrameSettings(s).widenStrong);
    s.setEnum("radius_mode", "path_density", "test");
    EXPECT_TRUE(resolveFrameSettings(s).widenStrong);
    s.setEnum("radius_mode", "density", "test");
    EXPECT_FALSE(resolveFrameSettings(s).widenStrong);
}

} // namespace
} // namespace ispm::test
