// The one table of render settings: every tunable is declared here once with its name, group,
// level, type, default, range, unit and one line of help. The JSON `render` block, `--set
// name=value`, the viewer's panels, the bench sweeps and the tables of README.md and
// docs/settings.md are all driven by this table.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ispm {

enum class SettingType { Int, Float, Enum };

// The groups settings are listed in (README.md, `ispm settings`, the viewer's headers), in order.
enum class SettingGroup { Image, Lights, Photons, Splat, Time, Post, ToneMap, Debug };
inline constexpr std::array<std::string_view, 8> kSettingGroupNames = {
    "image",           "lights and shadows", "photons", "splat and filter", "time and accumulation",
    "post-processing", "tone map",           "debug"};
std::string_view getGroupName(SettingGroup group);

// User settings are what a user of a renderer sets (README lists them, the viewer shows them);
// advanced ones tune the method (`ispm settings --all`, folded in the viewer).
enum class SettingLevel { User, Advanced };

// A help string is one line: what the setting does and its choices (docs/settings.md holds the
// why and the measurements).
inline constexpr size_t kMaxSettingHelpChars = 160;

struct SettingDesc {
    std::string_view name;
    SettingGroup group;
    SettingLevel level;
    SettingType type;
    double defaultValue;   // for Enum: index into choices
    double minValue;       // inclusive
    double maxValue;       // inclusive
    std::string_view unit; // "" when unitless
    std::string_view help;
    std::vector<std::string_view> choices; // Enum only
    // True when the default depends on the scene (derived at render time unless set).
    bool derived = false;
};

std::span<const SettingDesc> getSettingTable();
const SettingDesc* findSetting(std::string_view name);

// The user settings as one Markdown table, a group column first: what README.md shows between
// its settings-table markers, and `ispm settings` prints.
std::string formatUserSettingsMarkdown();
// Every setting, a section (### group) and a table per group with each setting's level: what
// docs/settings.md shows between its markers, and `ispm settings --all` prints.
std::string formatAllSettingsMarkdown();

class Settings;
// The overrides as a scene file's `render` block: enums by choice name, integers as integers
// (the viewer's "save", bench's report).
nlohmann::json formatRenderBlock(const Settings& settings);

// Values that differ from the table's defaults. Values are checked against the table on entry;
// a bad name or value throws InputError with `where` as context (a file and JSON path, or a flag).
class Settings {
  public:
    void set(std::string_view name, double value, const std::string& where);
    // Parses "name=value" as given on the command line (enum values by name).
    void setFromString(std::string_view assignment, const std::string& where);
    void setEnum(std::string_view name, std::string_view choice, const std::string& where);

    bool isSet(std::string_view name) const;
    double get(std::string_view name) const; // the override, else the table default
    int getInt(std::string_view name) const { return static_cast<int>(get(name)); }
    float getFloat(std::string_view name) const { return static_cast<float>(get(name)); }
    std::string_view getEnum(std::string_view name) const;

    // Layers `other`'s overrides on top of this one (command line over scene file).
    void merge(const Settings& other);
    const std::map<std::string, double, std::less<>>& getOverrides() const { return mValues; }

  private:
    std::map<std::string, double, std::less<>> mValues;
};

} // namespace ispm
