// The settings panel, generated from the one settings table (scene/settings.h): a widget per
// setting with its range, unit and help; derived settings can be left to the renderer. Also the
// "save" that writes the current settings as a scene `render` block.
#pragma once

#include "scene/settings.h"

#include <string>
#include <string_view>

namespace ispm {

// Settings the panel shows but does not edit: the window size decides them.
bool isWindowSetting(std::string_view name);

// Draws the widgets; returns true when `settings` changed.
bool drawSettingsPanel(Settings& settings);

// `settings` without an override of `name` (the table default, or derived, applies again).
Settings removeSetting(const Settings& settings, std::string_view name);

// Writes {"render": {...}}; throws std::runtime_error naming the path on failure.
void saveRenderBlock(const std::string& path, const Settings& settings);

} // namespace ispm
