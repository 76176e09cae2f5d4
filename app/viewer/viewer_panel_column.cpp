// The viewer's panel column: scene picker, view, reference, camera, settings, lights, animation
// and stats, right of the rendered region.
#include "viewer/viewer_app.h"

#include "core/strings.h"
#include "render/gpu_scene.h"
#include "render/photon_density_pass.h"
#include "render/splat_pass.h"
#include "scene/scene_loader.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <utility>

namespace ispm {
namespace {

constexpr float kMaxExposureStops = 20.0f; // the debug view's exposure slider
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
constexpr float kMaxStatusLines = 4.0f; // the message footer's height at most
const ImVec4 kErrorColour(1.0f, 0.4f, 0.4f, 1.0f);
const ImVec4 kOkColour(0.6f, 0.9f, 0.6f, 1.0f);

} // namespace

std::optional<double> findDerivedValue(const FrameRunner& runner, float luminanceMax,
                                       std::string_view name) {
    const FrameSettings& s = runner.getFrameSettings();
    const GpuScene& scene = runner.getPasses().scene;
    if (name == "splat_neighbours") return s.splatNeighbours;
    if (name == "denoise") return s.denoiseIterations;
    if (name == "shadow_map_size") return s.shadowMapSize;
    if (name == "luminance_max") {
        if (luminanceMax > 0.0f) return luminanceMax; // read back from the GPU every few frames
        return std::nullopt;
    }
    if (s.radiusMode == gpu::kRadiusDensity) {
        // radius_min is only a floor when set; dist_min and dist_max are not used.
        if (name == "radius_max")
            return computeDensityRadiusMax(scene.getSurfaceArea(), s.photons, s.splatNeighbours);
        return std::nullopt;
    }
    const SplatRadii r = computeSplatRadii(scene.getSurfaceArea(),
                                           glm::length(scene.getBounds().getExtent()), s, 1.0f);
    if (name == "radius_min") return r.radiusMinM;
    if (name == "radius_max") return r.radiusMaxM;
    if (name == "dist_min") return r.distMinM;
    if (name == "dist_max") return r.distMaxM;
    return std::nullopt;
}

std::vector<std::string> listScenesBeside(const std::string& scenePath) {
    const std::filesystem::path parent = std::filesystem::path(scenePath).parent_path();
    const std::filesystem::path folder = parent.empty() ? std::filesystem::path(".") : parent;
    std::vector<std::string> paths;
    std::error_code error; // an unreadable folder lists nothing
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (entry.path().extension() == ".json") paths.push_back(entry.path().string());
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

bool usesViewStops(const DebugView& view) {
    return !(view.source == DebugView::Source::Aov && view.aov == Aov::Display);
}

void Viewer::drawPanels() {
    const int renderWidth = mRunner->getFrameSettings().width;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(renderWidth), 0.0f));
    ImGui::SetNextWindowSize(
        ImVec2(static_cast<float>(kPanelWidthPx), static_cast<float>(mWindowHeight)));
    ImGui::Begin("ispm", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    // The message line (a file written, a path refused, the script's end) is a footer: visible
    // without scrolling, and its coming and going moves no widget above it.
    const float footerHeight = computeStatusFooterHeight();
    ImGui::BeginChild("panels", ImVec2(0.0f, -footerHeight));
    // Widgets leave room for the widest label on their right: none is cut at the panel's edge.
    ImGui::PushItemWidth(-computeSettingsLabelWidth());
    drawScenePicker();
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        const DebugView& current = mViews[static_cast<size_t>(mViewIndex)];
        if (ImGui::BeginCombo("debug view", current.name.c_str())) {
            for (size_t i = 0; i < mViews.size(); ++i) {
                if (ImGui::Selectable(mViews[i].name.c_str(), static_cast<int>(i) == mViewIndex)) {
                    mViewIndex = static_cast<int>(i);
                }
            }
            ImGui::EndCombo();
        }
        // Display is the tone-mapped frame: its brightness is the exposure setting.
        const bool stops = usesViewStops(current);
        ImGui::BeginDisabled(!stops);
        ImGui::SliderFloat("view stops", &mTransform.exposureStops, -kMaxExposureStops,
                           kMaxExposureStops);
        ImGui::EndDisabled();
        recordItem("view stops");
        if (!stops) {
            ImGui::SameLine();
            ImGui::TextDisabled("(?)");
            recordItem("view stops help");
            if (ImGui::IsItemHovered()) {
                showWrappedTooltip("view stops scale the linear views; display is tone mapped: "
                                   "set its brightness with the exposure setting");
            }
        }
        if (current.source == DebugView::Source::Reference) {
            // The region stays black without a reference: say why here, not only under the
            // (collapsed) Reference header.
            const std::string missing = mReference.describeMissing(
                mRunner->getFrameSettings().width, mRunner->getFrameSettings().height);
            if (!missing.empty()) {
                ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
                ImGui::TextWrapped("%s", missing.c_str());
                ImGui::PopStyleColor();
            }
        }
        int points = static_cast<int>(mPoints);
        if (ImGui::Combo("photon points", &points, kPhotonPointsNames.data(),
                         static_cast<int>(kPhotonPointsNames.size()))) {
            mPoints = static_cast<PhotonPoints>(points);
        }
        if (mPoints != PhotonPoints::None) {
            int colour = static_cast<int>(mPointsColour);
            if (ImGui::Combo("point colour", &colour, kPhotonColourNames.data(),
                             static_cast<int>(kPhotonColourNames.size()))) {
                mPointsColour = static_cast<PhotonColour>(colour);
            }
            drawPointColourLegend();
        }
        if (current.source == DebugView::Source::LightGBuffer ||
            current.source == DebugView::Source::LightImportance) {
            const int layers = mRunner->getPasses().lightViews.getGBuffer().getLayers();
            ImGui::SliderInt("light camera", &mTransform.lightLayer, 0, std::max(0, layers - 1));
        }
        ImGui::Checkbox("frame rate overlay (F2)", &mShowFrameRate);
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("F1: keys   F12: screenshot   F5: reload shaders   Ctrl+Q: quit");
        ImGui::PopStyleColor();
        if (!mShaderStatus.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, mShaderError ? kErrorColour : kOkColour);
            ImGui::TextWrapped("%s", mShaderStatus.c_str());
            ImGui::PopStyleColor();
        }
    }
    if (ImGui::CollapsingHeader("Reference")) mReference.drawPanel(*mRunner);
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        float speed = mFly.getSpeed();
        if (ImGui::DragFloat("speed m/s", &speed, speed * 0.01f, 1e-4f, 1e6f, "%.3g")) {
            mFly.setSpeed(speed);
        }
        const glm::vec3& p = mScene.camera.position;
        ImGui::Text("position %.3f %.3f %.3f", static_cast<double>(p.x), static_cast<double>(p.y),
                    static_cast<double>(p.z));
        if (ImGui::Button("reset camera")) mFly.reset(mScene.camera);
    }
    if (ImGui::CollapsingHeader("Settings", ImGuiTreeNodeFlags_DefaultOpen)) {
        // "save" first: the table is long.
        ImGui::InputText("##savepath", mSavePath.data(), mSavePath.size());
        recordItem("save path");
        ImGui::SameLine();
        if (ImGui::Button("save")) saveSettings(mSavePath.data());
        recordItem("save");
        Settings edited = mRunner->getSettings();
        const auto derived = [&](std::string_view name) {
            return findDerivedValue(*mRunner, mLuminanceMax, name);
        };
        if (drawSettingsPanel(edited, derived)) applySettings(edited);
    }
    if (ImGui::CollapsingHeader("Lights")) {
        const LightEdit edit =
            drawLightsPanel(mScene.lights, mScene.camera.position,
                            glm::length(mScene.computeWorldBounds().getExtent()));
        if (edit != LightEdit::None && mLightEdit != LightEdit::AddedOrRemoved) mLightEdit = edit;
    }
    if (mScene.isAnimated() && ImGui::CollapsingHeader("Animation")) drawAnimationPanel(mClock);
    if (ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawStatsPanel(mTimings, mCounts, mContext.getInfo().renderer,
                       gl::getTimingMethodName(mRunner->getTimings().method), mLuminanceMax,
                       mRunner->getPasses().accumulate.getAccumulatedFrames());
    }
    ImGui::PopItemWidth();
    ImGui::EndChild();
    if (!mStatus.empty()) {
        ImGui::Separator();
        ImGui::BeginChild("message");
        ImGui::PushStyleColor(ImGuiCol_Text, mStatusIsError ? kErrorColour : kOkColour);
        ImGui::TextWrapped("%s", mStatus.c_str());
        ImGui::PopStyleColor();
        ImGui::EndChild();
    }
    ImGui::End();
}

// The message's wrapped height, a few lines at most (a longer one scrolls), with the separator.
float Viewer::computeStatusFooterHeight() const {
    if (mStatus.empty()) return 0.0f;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = ImGui::GetContentRegionAvail().x;
    const float textHeight = ImGui::CalcTextSize(mStatus.c_str(), nullptr, false, width).y;
    const float maxHeight = kMaxStatusLines * ImGui::GetTextLineHeightWithSpacing();
    return std::min(textHeight, maxHeight) + 2.0f * style.ItemSpacing.y + style.WindowPadding.y;
}

void Viewer::recordItem(const std::string& name) {
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    mItems[name] = {{min.x, min.y}, {max.x, max.y}};
}

// Frame rate and time in the scene region's top-left corner, over the image (two lines: narrow
// regions too show both).
// F2: the UI's rate (it keeps its own, FramePacer) and the rendered frames' (drawn in slices).
void Viewer::drawFrameRateOverlay() {
    const double uiMs = mPacer.getMedianUiFrameMs();
    const double frameMs = mPacer.getLastRenderFrameMs();
    if (uiMs <= 0.0 || frameMs <= 0.0) return;
    std::array<char, kOverlayTextSize> text{};
    std::snprintf(text.data(), text.size(), "%.1f fps (%.0f ms)\nUI %.0f Hz", 1000.0 / frameMs,
                  frameMs, 1000.0 / uiMs);
    ImDrawList* list = ImGui::GetForegroundDrawList();
    list->PushClipRect(ImVec2(0.0f, 0.0f),
                       ImVec2(static_cast<float>(mRunner->getFrameSettings().width),
                              static_cast<float>(mWindowHeight)));
    const ImVec2 at(kOverlayMarginPx, kOverlayMarginPx);
    const ImVec2 size = ImGui::CalcTextSize(text.data());
    list->AddRectFilled(ImVec2(0.0f, 0.0f),
                        ImVec2(at.x + size.x + kOverlayMarginPx, at.y + size.y + kOverlayMarginPx),
                        ImGui::GetColorU32(ImVec4(0.0f, 0.0f, 0.0f, kOverlayAlpha)));
    list->AddText(at, IM_COL32_WHITE, text.data());
    list->PopClipRect();
}

// F1: what the keys and the mouse do.
void Viewer::drawHelp() {
    const ImVec2 centre(static_cast<float>(mWindowWidth) * 0.5f,
                        static_cast<float>(mWindowHeight) * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin("keys (F1 closes)", &mShowHelp,
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

void Viewer::drawScenePicker() {
    if (mScenePaths.empty()) return;
    const std::string current = std::filesystem::path(mScene.sourcePath).filename().string();
    if (!ImGui::BeginCombo("scene", current.c_str())) return;
    std::string picked;
    for (const std::string& path : mScenePaths) {
        const std::string name = std::filesystem::path(path).filename().string();
        if (ImGui::Selectable(name.c_str(), name == current)) picked = path;
    }
    ImGui::EndCombo();
    // Switched at the start of the next frame: this frame's panels still read the old runner.
    if (!picked.empty()) mPendingScenePath = picked;
}

void Viewer::drawPointColourLegend() const {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    switch (mPointsColour) {
    case PhotonColour::Kind:
        ImGui::TextWrapped("yellow: bounce photons (after the first bounce); cyan: result photons "
                           "(stored hits); each half its own power's hue");
        break;
    case PhotonColour::Direction:
        ImGui::TextWrapped("R, G, B = x, y, z of the direction, [-1, 1] -> [0, 1]: bounce photons "
                           "leaving the surface, result photons arriving");
        break;
    case PhotonColour::Power: {
        const double scale = computePhotonPowerScale(*mRunner);
        ImGui::TextWrapped("RGB power, gamma 2.2: white = %.3g W, %g x the mean a photon leaves "
                           "its light with (%.3g W)",
                           scale > 0.0 ? kPhotonPowerWhite / scale : 0.0, kPhotonPowerWhite,
                           scale > 0.0 ? 1.0 / scale : 0.0);
        break;
    }
    }
    ImGui::PopStyleColor();
}

} // namespace ispm
