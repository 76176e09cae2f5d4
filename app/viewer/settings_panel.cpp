// Settings widgets: drag fields whose speed follows the value's magnitude, so one widget serves
// ranges from 1e-6 to 1e9; Ctrl+click types a value.
#include "viewer/settings_panel.h"

#include "core/file_write.h"

#include "core/strings.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace ispm {
namespace {

constexpr double kDragFraction = 0.005; // of the current value per pixel dragged
constexpr double kMinFloatSpeed = 1e-4; // so a zero value can still be dragged away
constexpr float kMinIntSpeed = 0.2f;    // five pixels per step for small integers
constexpr int kJsonIndent = 2;
constexpr float kTooltipWidthEm = 28.0f; // tooltips wrap here: they fit beside the panel

const char* kWhere = "viewer settings panel";

void showHelp(const SettingDesc& d) {
    if (!ImGui::IsItemHovered()) return;
    const std::string unit = d.unit.empty() ? std::string() : strCat(" [", d.unit, "]");
    showWrappedTooltip(strCat(d.help, unit, "\nrange ", d.minValue, " .. ", d.maxValue));
}

bool drawValue(const SettingDesc& d, Settings& settings) {
    const std::string label(d.name);
    double value = settings.get(d.name);
    bool changed = false;
    switch (d.type) {
    case SettingType::Enum: {
        int index = static_cast<int>(value);
        const std::string current(d.choices[static_cast<size_t>(index)]);
        if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
            for (size_t i = 0; i < d.choices.size(); ++i) {
                const std::string choice(d.choices[i]);
                if (ImGui::Selectable(choice.c_str(), static_cast<int>(i) == index)) {
                    index = static_cast<int>(i);
                    changed = true;
                }
            }
            ImGui::EndCombo();
        }
        value = index;
        break;
    }
    case SettingType::Int: {
        int v = static_cast<int>(value);
        const int lo = static_cast<int>(d.minValue);
        const int hi = static_cast<int>(d.maxValue);
        const float speed =
            std::max(kMinIntSpeed, static_cast<float>(std::abs(value) * kDragFraction));
        changed = ImGui::DragScalar(label.c_str(), ImGuiDataType_S32, &v, speed, &lo, &hi, "%d",
                                    ImGuiSliderFlags_AlwaysClamp);
        value = v;
        break;
    }
    case SettingType::Float: {
        const double speed = std::max(kMinFloatSpeed, std::abs(value) * kDragFraction);
        changed = ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &value,
                                    static_cast<float>(speed), &d.minValue, &d.maxValue, "%.4g",
                                    ImGuiSliderFlags_AlwaysClamp);
        break;
    }
    }
    showHelp(d);
    if (changed) settings.set(d.name, value, kWhere);
    return changed;
}

} // namespace

void showWrappedTooltip(const std::string& text) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * kTooltipWidthEm);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

float computeSettingsLabelWidth() {
    float width = 0.0f;
    for (const SettingDesc& d : getSettingTable()) {
        const std::string name(d.name);
        width = std::max(width, ImGui::CalcTextSize(name.c_str()).x);
    }
    return width + ImGui::GetStyle().ItemInnerSpacing.x;
}

bool isWindowSetting(std::string_view name) {
    return name == "width" || name == "height";
}

Settings removeSetting(const Settings& settings, std::string_view name) {
    Settings result;
    for (const auto& [key, value] : settings.getOverrides()) {
        if (key != name) result.set(key, value, kWhere);
    }
    return result;
}

double computeUntickedValue(const SettingDesc& desc, std::optional<double> derived) {
    const double value = derived.value_or(desc.defaultValue);
    const double clamped = std::clamp(value, desc.minValue, desc.maxValue);
    return desc.type == SettingType::Int ? std::round(clamped) : clamped;
}

namespace {

// One setting's row: a widget, or for a derived setting an "auto" box and the derived value.
bool drawSetting(const SettingDesc& d, Settings& settings, const DerivedValues& derived) {
    bool changed = false;
    ImGui::PushID(d.name.data(), d.name.data() + d.name.size());
    if (isWindowSetting(d.name)) {
        ImGui::Text("%s: %d (follows the window)", std::string(d.name).c_str(),
                    settings.getInt(d.name));
    } else if (d.derived) {
        // Derived settings: "auto" leaves the value to the renderer (from the scene).
        bool isAuto = !settings.isSet(d.name);
        const std::optional<double> value = derived(d.name);
        if (ImGui::Checkbox("auto", &isAuto)) {
            settings = isAuto ? removeSetting(settings, d.name) : settings;
            if (!isAuto) settings.set(d.name, computeUntickedValue(d, value), kWhere);
            changed = true;
        }
        ImGui::SameLine();
        if (isAuto) {
            // Wrapped: a long unit must not run past the panel's edge.
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            if (value) {
                ImGui::TextWrapped("%s = %.4g %s (derived)", std::string(d.name).c_str(), *value,
                                   std::string(d.unit).c_str());
            } else {
                ImGui::TextWrapped("%s (derived)", std::string(d.name).c_str());
            }
            ImGui::PopStyleColor();
            showHelp(d);
        } else {
            changed = drawValue(d, settings);
        }
    } else {
        changed = drawValue(d, settings);
    }
    ImGui::PopID();
    return changed;
}

// The settings of one group at one level, in table order.
bool drawSettings(SettingGroup group, SettingLevel level, Settings& settings,
                  const DerivedValues& derived) {
    bool changed = false;
    for (const SettingDesc& d : getSettingTable()) {
        if (d.group == group && d.level == level) changed |= drawSetting(d, settings, derived);
    }
    return changed;
}

bool hasSettings(SettingGroup group, SettingLevel level) {
    const auto table = getSettingTable();
    return std::any_of(table.begin(), table.end(),
                       [&](const SettingDesc& d) { return d.group == group && d.level == level; });
}

} // namespace

bool drawSettingsPanel(Settings& settings, const DerivedValues& derived) {
    bool changed = false;
    ImGui::PushID("settings groups"); // group names apart from the panel column's headers
    for (size_t g = 0; g < kSettingGroupNames.size(); ++g) {
        const auto group = static_cast<SettingGroup>(g);
        const std::string name(kSettingGroupNames[g]);
        if (!ImGui::CollapsingHeader(name.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
        ImGui::PushID(name.c_str());
        changed |= drawSettings(group, SettingLevel::User, settings, derived);
        // The method's own knobs, folded until asked for.
        if (hasSettings(group, SettingLevel::Advanced) && ImGui::TreeNode("advanced")) {
            changed |= drawSettings(group, SettingLevel::Advanced, settings, derived);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    ImGui::PopID();
    return changed;
}

void saveRenderBlock(const std::string& path, const Settings& settings) {
    const nlohmann::json document = {{"render", formatRenderBlock(settings)}};
    try {
        writeFileWhole(path, document.dump(kJsonIndent) + "\n");
    } catch (const std::runtime_error&) {
        throw std::runtime_error(strCat(path, ": cannot write the render block"));
    }
}

} // namespace ispm
