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
#include <filesystem>

namespace ispm {
namespace {

constexpr float kMaxExposureStops = 20.0f; // the debug view's exposure slider

} // namespace

std::optional<double> findDerivedValue(const FrameRunner& runner, float luminanceMax,
                                       std::string_view name) {
    const FrameSettings& s = runner.getFrameSettings();
    const GpuScene& scene = runner.getGpuScene();
    if (name == "splat_neighbours") return s.splatNeighbours;
    if (name == "denoise") return s.denoiseIterations;
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

void Viewer::drawPanels() {
    const int renderWidth = mRunner->getWidth();
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(renderWidth), 0.0f));
    ImGui::SetNextWindowSize(
        ImVec2(static_cast<float>(kPanelWidthPx), static_cast<float>(mWindowHeight)));
    ImGui::Begin("ispm", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
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
        ImGui::SliderFloat("view stops", &mTransform.exposureStops, -kMaxExposureStops,
                           kMaxExposureStops);
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
            const int layers = mRunner->getLightGBuffer().getLayers();
            ImGui::SliderInt("light camera", &mTransform.lightLayer, 0, std::max(0, layers - 1));
        }
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("F12: screenshot   F5: reload shaders   drag: look   WASD/QE: fly   "
                           "wheel: speed");
        ImGui::PopStyleColor();
        if (!mShaderStatus.empty()) {
            const ImVec4 kErrorColour(1.0f, 0.4f, 0.4f, 1.0f);
            const ImVec4 kOkColour(0.6f, 0.9f, 0.6f, 1.0f);
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
        Settings edited = mRunner->getSettings();
        const auto derived = [&](std::string_view name) {
            return findDerivedValue(*mRunner, mLuminanceMax, name);
        };
        if (drawSettingsPanel(edited, derived)) applySettings(edited);
        ImGui::InputText("##savepath", mSavePath.data(), mSavePath.size());
        ImGui::SameLine();
        if (ImGui::Button("save")) {
            try { // an unwritable path is reported here, the viewer goes on
                saveRenderBlock(mSavePath.data(), mRunner->getSettings());
                mStatus = strCat("saved the render block to ", mSavePath.data());
            } catch (const std::runtime_error& e) {
                mStatus = e.what();
            }
        }
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
                       gl::getTimingMethodName(mRunner->getTimingMethod()), mLuminanceMax,
                       mRunner->getAccumulatedFrames());
    }
    if (!mStatus.empty()) ImGui::TextWrapped("%s", mStatus.c_str());
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
