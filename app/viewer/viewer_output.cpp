// ViewerOutput: each file the viewer writes says so on the message line with its absolute path,
// and the line itself, drawn as a footer under the panels.
#include "viewer/viewer_output.h"

#include "core/strings.h"
#include "image/image_io.h"
#include "render/readback.h"
#include "viewer/screenshot.h"
#include "viewer/settings_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace ispm {
namespace {

constexpr float kMaxStatusLines = 4.0f; // the message footer's height at most
const ImVec4 kErrorColour(1.0f, 0.4f, 0.4f, 1.0f);
const ImVec4 kOkColour(0.6f, 0.9f, 0.6f, 1.0f);

} // namespace

void ViewerOutput::setStatus(const std::string& text, bool isError) {
    mStatus = text;
    mStatusIsError = isError;
    std::FILE* out = isError ? stderr : stdout;
    std::fprintf(out, "%s\n", text.c_str());
    std::fflush(out);
}

void ViewerOutput::takeScreenshot(const std::string& path, int windowWidth, int windowHeight) {
    writeScreenshot(path, windowWidth, windowHeight);
    setStatus(strCat("wrote ", std::filesystem::absolute(path).string(), " (", windowWidth, "x",
                     windowHeight, " window)"),
              false);
}

void ViewerOutput::takeNumberedScreenshot(int windowWidth, int windowHeight) {
    std::string path;
    std::error_code error;
    do {
        path = strCat("ispm_screenshot_", mScreenshotCount++, ".png");
    } while (std::filesystem::exists(path, error));
    try {
        takeScreenshot(path, windowWidth, windowHeight);
    } catch (const std::runtime_error& e) {
        setStatus(e.what(), true);
    }
}

void ViewerOutput::saveSettings(const std::string& path, const Settings& settings) {
    try {
        writeSettings(path, settings);
    } catch (const std::runtime_error& e) {
        setStatus(e.what(), true);
    }
}

void ViewerOutput::writeSettings(const std::string& path, const Settings& settings) {
    saveRenderBlock(path, settings);
    setStatus(
        strCat("wrote the settings (a render block) to ", std::filesystem::absolute(path).string()),
        false);
}

void ViewerOutput::writeAov(const std::string& path, const std::string& aovName,
                            const std::string& where, const FrameRunner& runner) {
    const Aov aov = aovName == "display" ? Aov::Display : parseAov(aovName, where);
    writeImage(path, readTextureImage(runner.getAov(aov)));
    std::printf("wrote %s (%s)\n", path.c_str(), aovName.c_str());
    std::fflush(stdout);
}

// Sized before the panels are drawn: the line's coming and going moves no widget above it.
float ViewerOutput::computeFooterHeight() const {
    if (mStatus.empty()) return 0.0f;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = ImGui::GetContentRegionAvail().x;
    const float textHeight = ImGui::CalcTextSize(mStatus.c_str(), nullptr, false, width).y;
    const float maxHeight = kMaxStatusLines * ImGui::GetTextLineHeightWithSpacing();
    return std::min(textHeight, maxHeight) + 2.0f * style.ItemSpacing.y + style.WindowPadding.y;
}

void ViewerOutput::drawFooter() const {
    if (mStatus.empty()) return;
    ImGui::Separator();
    ImGui::BeginChild("message");
    drawMessageText(mStatus, mStatusIsError);
    ImGui::EndChild();
}

void drawMessageText(const std::string& text, bool isError) {
    ImGui::PushStyleColor(ImGuiCol_Text, isError ? kErrorColour : kOkColour);
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

} // namespace ispm
