// The settings panel, generated from the one settings table (settings/settings.h): a widget per
// setting with its range, unit and help; derived settings can be left to the renderer. Also the
// "save" that writes the current settings as a scene `render` block.
#pragma once

#include "settings/settings.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace ispm {

// A tooltip whose text wraps at a readable width instead of running off the window's edge.
void showWrappedTooltip(const std::string& text);

// The widest setting name in the current font, with the gap before it: the room the panels keep
// right of their widgets for labels (the other panels' labels are shorter).
float computeSettingsLabelWidth();

// Settings the panel shows but does not edit: the window size decides them.
bool isWindowSetting(std::string_view name);

// The value a derived setting takes now (what "auto" gives), when the caller knows it.
using DerivedValues = std::function<std::optional<double>(std::string_view name)>;

// Draws the widgets by group, each group a collapsing header with its advanced settings folded
// in a tree node, each derived setting's current value beside its "auto"; returns true when
// `settings` changed.
bool drawSettingsPanel(Settings& settings, const DerivedValues& derived);

// The value a derived setting starts from when "auto" is unticked: the derived value it had,
// within the setting's range; the table default when it is not known.
double computeUntickedValue(const SettingDesc& desc, std::optional<double> derived);

// `settings` without an override of `name` (the table default, or derived, applies again).
Settings removeSetting(const Settings& settings, std::string_view name);

// Writes {"render": {...}}; throws std::runtime_error naming the path on failure.
void saveRenderBlock(const std::string& path, const Settings& settings);

} // namespace ispm
