// The F2 overlay on the foreground draw list (over the image, under nothing) and the F1 window
// with one line per key.
#include "viewer/viewer_overlays.h"

#include <imgui.h>

#include <array>
#include <cstdio>
#include <utility>

namespace ispm {
namespace {

constexpr float kOverlayMarginPx = 4.0f;
constexpr float kOverlayAlpha = 0.6f; // the frame-rate overlay's backing
constexpr size_t kOverlayTextSize = 64;
constexpr float kHelpKeyColumnEm = 8.0f; // where the help window's descriptions start
constexpr std::array<std::pair<const char*, const char*>, 12> kHelpLines = {{
    {"W A S D", "fly forward, left, back, right"},
    {"Q / E", "fly down / up"},
    {"left drag", "look around (in the scene region)"},
    {"wheel", "flying speed (in the scene region)"},
    {"F1", "this help"},
    {"F2", "frame rate overlay on/off"},
    {"F5", "reload the shaders that changed on disk"},
    {"F12", "screenshot (ispm_screenshot_N.png, this folder)"},
    {"Ctrl+Q", "quit"},
    {"Ctrl+click", "type a value into a slider or drag field"},
    {"hover", "a setting's help, unit and range"},
    {"Esc", "leave a text field without applying it"},
}};

} // namespace

// Two lines: narrow regions too show both.
void drawFrameRateOverlay(const FramePacer& pacer, int regionWidth, int regionHeight) {
    const double uiMs = pacer.getMedianUiFrameMs();
    const double frameMs = pacer.getLastRenderFrameMs();
    if (uiMs <= 0.0 || frameMs <= 0.0) return;
    std::array<char, kOverlayTextSize> text{};
    std::snprintf(text.data(), text.size(), "%.1f fps (%.0f ms)\nUI %.0f Hz", 1000.0 / frameMs,
                  frameMs, 1000.0 / uiMs);
    ImDrawList* list = ImGui::GetForegroundDrawList();
    list->PushClipRect(ImVec2(0.0f, 0.0f),
                       ImVec2(static_cast<float>(regionWidth), static_cast<float>(regionHeight)));
    const ImVec2 at(kOverlayMarginPx, kOverlayMarginPx);
    const ImVec2 size = ImGui::CalcTextSize(text.data());
    list->AddRectFilled(ImVec2(0.0f, 0.0f),
                        ImVec2(at.x + size.x + kOverlayMarginPx, at.y + size.y + kOverlayMarginPx),
                        ImGui::GetColorU32(ImVec4(0.0f, 0.0f, 0.0f, kOverlayAlpha)));
    list->AddText(at, IM_COL32_WHITE, text.data());
    list->PopClipRect();
}

void drawHelpWindow(bool& isOpen, int windowWidth, int windowHeight) {
    const ImVec2 centre(static_cast<float>(windowWidth) * 0.5f,
                        static_cast<float>(windowHeight) * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin("keys (F1 closes)", &isOpen,
                      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                          ImGuiWindowFlags_NoCollapse)) {
        ImGui::End();
        return;
    }
    for (const auto& [key, what] : kHelpLines) {
        ImGui::TextUnformatted(key);
        ImGui::SameLine(ImGui::GetFontSize() * kHelpKeyColumnEm);
        ImGui::TextUnformatted(what);
    }
    ImGui::End();
}

} // namespace ispm
