// PanelColumn: one ImGui window at the right of the rendered region whose collapsing headers hold
// the panels, and the state the panels edit; the message line is a footer under them.
#include "viewer/viewer_panel_column.h"

#include "render/gpu_scene.h"
#include "render/photon_density_pass.h"
#include "render/splat_radii.h"
#include "viewer/settings_panel.h"
#include "viewer/viewer_overlays.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace ispm {
namespace {

constexpr float kMaxExposureStops = 20.0f; // the debug view's exposure slider
// Stats-panel read-backs (photon counts, white point) every this many frames: a few times a
// second at interactive rates, instead of a GPU wait every frame.
constexpr uint64_t kStatsReadbackFrames = 8;

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

PanelColumn::PanelColumn(const std::string& scenePath) : mScenePaths(listScenesBeside(scenePath)) {}

PanelRequests PanelColumn::draw(const PanelContext& context) {
    PanelRequests requests;
    FrameRunner& runner = context.runner;
    Scene& scene = context.scene;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(runner.getFrameSettings().width), 0.0f));
    ImGui::SetNextWindowSize(
        ImVec2(static_cast<float>(kPanelWidthPx), static_cast<float>(context.windowHeight)));
    ImGui::Begin("ispm", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    // The message line (a file written, a path refused, the script's end) is a footer: visible
    // without scrolling, and its coming and going moves no widget above it.
    const float footerHeight = context.output.computeFooterHeight();
    ImGui::BeginChild("panels", ImVec2(0.0f, -footerHeight));
    // Widgets leave room for the widest label on their right: none is cut at the panel's edge.
    ImGui::PushItemWidth(-computeSettingsLabelWidth());
    drawScenePicker(context, requests);
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) drawViewSection(context);
    if (ImGui::CollapsingHeader("Reference")) context.reference.drawPanel(runner);
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        float speed = context.fly.getSpeed();
        if (ImGui::DragFloat("speed m/s", &speed, speed * 0.01f, 1e-4f, 1e6f, "%.3g")) {
            context.fly.setSpeed(speed);
        }
        const glm::vec3& p = scene.camera.position;
        ImGui::Text("position %.3f %.3f %.3f", static_cast<double>(p.x), static_cast<double>(p.y),
                    static_cast<double>(p.z));
        if (ImGui::Button("reset camera")) context.fly.reset(scene.camera);
    }
    if (ImGui::CollapsingHeader("Settings", ImGuiTreeNodeFlags_DefaultOpen)) {
        // "save" first: the table is long.
        ImGui::InputText("##savepath", mSavePath.data(), mSavePath.size());
        recordItem("save path");
        ImGui::SameLine();
        if (ImGui::Button("save"))
            context.output.saveSettings(mSavePath.data(), runner.getSettings());
        recordItem("save");
        Settings edited = runner.getSettings();
        const auto derived = [&](std::string_view name) {
            return findDerivedValue(runner, mLuminanceMax, name);
        };
        if (drawSettingsPanel(edited, derived)) context.applySettings(edited);
    }
    if (ImGui::CollapsingHeader("Lights")) {
        requests.lightEdit = drawLightsPanel(scene.lights, scene.camera.position,
                                             glm::length(scene.computeWorldBounds().getExtent()));
    }
    if (scene.isAnimated() && ImGui::CollapsingHeader("Animation")) {
        drawAnimationPanel(context.clock);
    }
    if (ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawStatsPanel(mTimings, mCounts, context.window.getInfo().renderer,
                       gl::getTimingMethodName(runner.getTimings().method), mLuminanceMax,
                       runner.getPasses().accumulate.getAccumulatedFrames());
    }
    ImGui::PopItemWidth();
    ImGui::EndChild();
    context.output.drawFooter();
    ImGui::End();
    if (mShowFrameRate)
        drawFrameRateOverlay(context.pacer, runner.getFrameSettings().width, context.windowHeight);
    if (mShowHelp) drawHelpWindow(mShowHelp, context.windowWidth, context.windowHeight);
    return requests;
}

void PanelColumn::drawViewSection(const PanelContext& context) {
    const DebugView& current = getView();
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
    const FrameRunner& runner = context.runner;
    if (current.source == DebugView::Source::Reference) {
        // The region stays black without a reference: say why here, not only under the
        // (collapsed) Reference header.
        const std::string missing = context.reference.describeMissing(
            runner.getFrameSettings().width, runner.getFrameSettings().height);
        if (!missing.empty()) drawMessageText(missing, true);
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
        drawPointColourLegend(runner);
    }
    if (current.source == DebugView::Source::LightGBuffer ||
        current.source == DebugView::Source::LightImportance) {
        const int layers = runner.getPasses().lightViews.getGBuffer().getLayers();
        ImGui::SliderInt("light camera", &mTransform.lightLayer, 0, std::max(0, layers - 1));
    }
    ImGui::Checkbox("frame rate overlay (F2)", &mShowFrameRate);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("F1: keys   F12: screenshot   F5: reload shaders   Ctrl+Q: quit");
    ImGui::PopStyleColor();
    if (!mShaderStatus.empty()) drawMessageText(mShaderStatus, mShaderError);
}

void PanelColumn::setShaderStatus(const std::string& text, bool isError) {
    mShaderStatus = text;
    mShaderError = isError;
}

bool PanelColumn::selectView(const std::string& name) {
    const int index = findDebugView(mViews, name);
    if (index < 0) return false;
    mViewIndex = index;
    return true;
}

void PanelColumn::selectPoints(const std::string& points, const std::string& colour) {
    for (size_t i = 0; i < kPhotonPointsNames.size(); ++i) {
        if (points == kPhotonPointsNames[i]) mPoints = static_cast<PhotonPoints>(i);
    }
    for (size_t i = 0; i < kPhotonColourNames.size(); ++i) {
        if (colour == kPhotonColourNames[i]) mPointsColour = static_cast<PhotonColour>(i);
    }
}

// Counts and the white point are read back for the Stats panel only, every few frames: a
// read-back waits for the GPU to finish the frame.
void PanelColumn::readStats(const FrameRunner& runner) {
    if (mFrameIndex++ % kStatsReadbackFrames != 0) return;
    mCounts = readPhotonCounts(runner);
    mLuminanceMax = runner.getPasses().tonemap.readLuminanceMax();
}

// The frame row counts the in-viewer path tracer too, when it ran this frame.
void PanelColumn::recordTimings(const FrameRunner& runner, const ReferenceView& reference) {
    std::vector<PassTiming> timings = runner.getTimings().passes;
    if (const std::optional<PassTiming> traced = reference.getFrameTiming()) {
        timings.push_back(*traced);
    }
    mTimings.record(timings);
}

// Its message lines and the Stats frame time, and the window's clocks: rendered frames in wall
// time (their slices and the UI frames between them) and the UI frames' median interval.
void PanelColumn::print(const PanelContext& context) const {
    std::printf("panel status: %s\n", context.output.getStatus().c_str());
    std::printf("panel title: %s\n", context.window.getTitle().c_str());
    std::printf("panel metrics: %s\n", context.reference.getMetricsText().c_str());
    std::printf("panel reference: %s\n", context.reference.getStatus().c_str());
    const glm::vec3& p = context.scene.camera.position;
    std::printf("panel camera: %.6f %.6f %.6f\n", static_cast<double>(p.x),
                static_cast<double>(p.y), static_cast<double>(p.z));
    std::printf("panel frame ms: %.6f\n", mTimings.getLastTotalMs());
    std::printf("panel frame wall ms: %.6f\n", context.pacer.getLastRenderFrameMs());
    std::printf("panel ui frame ms: %.6f\n", context.pacer.getMedianUiFrameMs());
    std::printf("panel ui frame max ms: %.6f\n", context.pacer.getMaxUiFrameMs());
    std::printf("panel ui frames per frame: %d\n", context.pacer.getUiFramesPerRenderFrame());
    for (const PassTiming& t : mTimings.getLast())
        std::printf("panel pass ms: %s = %.6f\n", t.name.c_str(), t.ms);
    std::printf("panel view stops: %s\n", usesViewStops(getView()) ? "on" : "off");
    std::fflush(stdout);
}

void PanelColumn::recordItem(const std::string& name) {
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    mItems[name] = {{min.x, min.y}, {max.x, max.y}};
}

void PanelColumn::drawScenePicker(const PanelContext& context, PanelRequests& requests) const {
    if (mScenePaths.empty()) return;
    const std::string current = std::filesystem::path(context.scene.sourcePath).filename().string();
    if (!ImGui::BeginCombo("scene", current.c_str())) return;
    std::string picked;
    for (const std::string& path : mScenePaths) {
        const std::string name = std::filesystem::path(path).filename().string();
        if (ImGui::Selectable(name.c_str(), name == current)) picked = path;
    }
    ImGui::EndCombo();
    // Switched at the start of the next frame: this frame's panels still read the old runner.
    if (!picked.empty()) requests.scenePath = picked;
}

void PanelColumn::drawPointColourLegend(const FrameRunner& runner) const {
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
        const double scale = computePhotonPowerScale(runner);
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
