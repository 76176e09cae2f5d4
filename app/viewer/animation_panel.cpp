// Animation panel widgets. The scrubber's range grows with the time played, so it never clamps
// the clock, and starts at a minute so a short scene can be scrubbed finely.
#include "viewer/animation_panel.h"

#include <imgui.h>

#include <algorithm>

namespace ispm {

namespace {

constexpr double kMinScrubRangeS = 60.0;
constexpr float kMaxSpeed = 8.0f;     // faster than this a 30 Hz software frame skips whole motions
constexpr double kStepS = 1.0 / 60.0; // one 60 Hz frame: the step bench --animate uses

} // namespace

bool advanceAnimationClock(AnimationClock& clock, double wallSeconds) {
    if (clock.isPlaying) clock.timeS += wallSeconds * static_cast<double>(clock.speed);
    if (clock.timeS == clock.appliedTimeS) return false;
    clock.appliedTimeS = clock.timeS;
    return true;
}

void drawAnimationPanel(AnimationClock& clock) {
    if (ImGui::Button(clock.isPlaying ? "pause" : "play")) clock.isPlaying = !clock.isPlaying;
    ImGui::SameLine();
    if (ImGui::Button("step")) {
        clock.isPlaying = false;
        clock.timeS += kStepS;
    }
    ImGui::SameLine();
    if (ImGui::Button("reset")) clock.timeS = 0.0;
    const double zero = 0.0;
    const double range = std::max(kMinScrubRangeS, clock.timeS);
    ImGui::SliderScalar("time s", ImGuiDataType_Double, &clock.timeS, &zero, &range, "%.3f");
    ImGui::SliderFloat("speed", &clock.speed, 0.0f, kMaxSpeed, "%.2fx");
}

} // namespace ispm
