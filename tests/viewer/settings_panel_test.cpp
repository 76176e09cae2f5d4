// The settings panel's "auto" checkbox: unticked, a derived setting starts from the value it was
// given (not the range's minimum), kept within the setting's range.
#include "viewer/settings_panel.h"

#include <gtest/gtest.h>

namespace ispm {
namespace {

TEST(SettingsPanel, UntickedAutoStartsFromTheDerivedValue) {
    const SettingDesc* neighbours = findSetting("splat_neighbours");
    ASSERT_NE(neighbours, nullptr);
    EXPECT_EQ(computeUntickedValue(*neighbours, 101.0), 101.0);
    // An int setting takes a whole number; a value past the range stops at its end.
    EXPECT_EQ(computeUntickedValue(*neighbours, 100.6), 101.0);
    EXPECT_EQ(computeUntickedValue(*neighbours, 1e9), neighbours->maxValue);
    const SettingDesc* radiusMax = findSetting("radius_max");
    ASSERT_NE(radiusMax, nullptr);
    EXPECT_DOUBLE_EQ(computeUntickedValue(*radiusMax, 0.0734), 0.0734);
    // Not known (a white point not read back yet): the table's default, within the range.
    const SettingDesc* white = findSetting("luminance_max");
    ASSERT_NE(white, nullptr);
    const double fallback = computeUntickedValue(*white, std::nullopt);
    EXPECT_GE(fallback, white->minValue);
    EXPECT_LE(fallback, white->maxValue);
}

} // namespace
} // namespace ispm
