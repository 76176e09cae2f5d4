// Stats and lights panels.
#include "viewer/viewer_panels.h"

#include <imgui.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace ispm {
namespace {

constexpr size_t kHistoryFrames = 120; // two seconds at 60 Hz
constexpr float kPlotHeightPx = 60.0f;
constexpr float kPositionFraction = 1e-3f;    // of the scene's size per pixel dragged
constexpr float kDirectionSpeed = 0.005f;     // unit vector components per pixel
constexpr float kPowerFraction = 5e-3f;       // of the light's largest component per pixel
constexpr float kMinPowerSpeed = 1e-3f;       // so a black light can be dragged up
constexpr float kAngleSpeed = 0.1f;           // degrees per pixel
constexpr float kMaxPower = 1e9f;             // W/sr or W/m^2: far beyond any scene, bounds drags
constexpr float kMaxConeDeg = 89.0f;          // a spot camera's half-angle must stay under 90
constexpr glm::vec3 kNewLightIntensity{1.0f}; // W/sr: a dim white bulb, when no light to copy

float computePowerSpeed(const glm::vec3& power) {
    return std::max(kMinPowerSpeed, kPowerFraction * std::max({power.x, power.y, power.z}));
}

} // namespace

void TimingHistory::record(const std::vector<PassTiming>& timings) {
    mLast = timings;
    float total = 0.0f;
    for (const PassTiming& t : timings)
        total += static_cast<float>(t.ms);
    mTotals.push_back(total);
    while (mTotals.size() > kHistoryFrames)
        mTotals.pop_front();
}

double TimingHistory::getLastTotalMs() const {
    double total = 0.0;
    for (const PassTiming& t : mLast)
        total += t.ms;
    return total;
}

void drawStatsPanel(const TimingHistory& timings, const PhotonCounts& counts,
                    const std::string& renderer, const char* timingMethod, float luminanceMax,
                    uint32_t accumulatedFrames) {
    ImGui::TextWrapped("GL renderer: %s", renderer.c_str());
    ImGui::Text("pass times by %s", timingMethod);
    if (ImGui::BeginTable("timings", 2, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("ms");
        ImGui::TableHeadersRow();
        for (const PassTiming& t : timings.getLast()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(t.name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%8.2f", t.ms);
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("frame");
        ImGui::TableNextColumn();
        ImGui::Text("%8.2f", timings.getLastTotalMs());
        ImGui::EndTable();
    }
    const std::vector<float> totals = timings.getFrameTotals();
    if (!totals.empty()) {
        const float peak = *std::max_element(totals.begin(), totals.end());
        ImGui::PlotLines("frame ms", totals.data(), static_cast<int>(totals.size()), 0, nullptr,
                         0.0f, peak * 1.1f, ImVec2(0.0f, kPlotHeightPx));
    }
    ImGui::Text("photons emitted  %u", counts.emitted);
    ImGui::Text("after bounce 1   %u", counts.bounced);
    ImGui::Text("stored           %u", counts.stored);
    ImGui::Text("stored in view   %u", counts.inView);
    ImGui::Text("overflow         %u", counts.overflow);
    ImGui::Text("luminance max    %.4g W/(m^2 sr)", static_cast<double>(luminanceMax));
    // Frames of the still view (setting `accumulate`): a move starts the count again, a light or
    // setting change the whole history.
    ImGui::Text("frames averaged  %u", accumulatedFrames);
}

LightEdit drawLightsPanel(std::vector<Light>& lights, const glm::vec3& newLightPositionW,
                          float sceneSizeM) {
    const float positionSpeed = kPositionFraction * sceneSizeM;
    bool changed = false;
    size_t removeIndex = lights.size();
    for (size_t i = 0; i < lights.size(); ++i) {
        Light& light = lights[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::Text("light %zu: %s", i, getLightTypeName(light.type));
        // The last light stays: a scene without lights has nothing to show.
        if (lights.size() > 1) {
            ImGui::SameLine();
            if (ImGui::SmallButton("remove")) removeIndex = i;
        }
        if (light.type != LightType::Sun) {
            changed |=
                ImGui::DragFloat3("position m", glm::value_ptr(light.position), positionSpeed);
            changed |= ImGui::DragFloat3("intensity W/sr", glm::value_ptr(light.intensity),
                                         computePowerSpeed(light.intensity), 0.0f, kMaxPower);
        } else {
            changed |= ImGui::DragFloat3("irradiance W/m^2", glm::value_ptr(light.irradiance),
                                         computePowerSpeed(light.irradiance), 0.0f, kMaxPower);
        }
        if (light.type != LightType::Point) {
            if (ImGui::DragFloat3("direction", glm::value_ptr(light.direction), kDirectionSpeed)) {
                // The renderer expects a unit direction; a zero vector keeps the old one.
                const float length = glm::length(light.direction);
                light.direction = length > 0.0f ? light.direction / length : glm::vec3(0, -1, 0);
                changed = true;
            }
        }
        if (light.type == LightType::Spot) {
            changed |=
                ImGui::DragFloat("inner deg", &light.innerDeg, kAngleSpeed, 0.0f, kMaxConeDeg);
            changed |=
                ImGui::DragFloat("outer deg", &light.outerDeg, kAngleSpeed, 0.0f, kMaxConeDeg);
            light.innerDeg = std::min(light.innerDeg, light.outerDeg);
        }
        ImGui::Separator();
        ImGui::PopID();
    }
    if (removeIndex < lights.size()) {
        lights.erase(lights.begin() + static_cast<std::ptrdiff_t>(removeIndex));
        return LightEdit::AddedOrRemoved;
    }
    if (ImGui::Button("add point light at the camera")) {
        Light light;
        light.type = LightType::Point;
        light.position = newLightPositionW;
        const bool canCopy = !lights.empty() && lights.front().type != LightType::Sun;
        light.intensity = canCopy ? lights.front().intensity : kNewLightIntensity;
        lights.push_back(light);
        return LightEdit::AddedOrRemoved;
    }
    return changed ? LightEdit::Values : LightEdit::None;
}

} // namespace ispm
