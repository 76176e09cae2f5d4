// The one table of render settings: every tunable is declared here once with its name, type,
// default, range, unit and help. The JSON `render` block, `--set name=value`, the viewer's panels
// and the bench sweeps are all driven by this table.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ispm {

enum class SettingType { Int, Float, Enum };

struct SettingDesc {
    std::string_view name;
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

// The table as Markdown (name, type, default, range, unit, meaning): what README.md and
// docs/scene-format.md show between their settings-table markers, and `ispm settings` prints.
std::string formatSettingsMarkdown();

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
