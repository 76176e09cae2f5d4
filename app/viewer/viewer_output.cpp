// The viewer's files and its message line: screenshots (F12, --screenshot, scripts), the
// settings' "save", and the footer line under the panels that says what was written, and where.
#include "viewer/viewer_app.h"

#include "core/strings.h"
#include "viewer/screenshot.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace ispm {

void Viewer::takeScreenshot(const std::string& path) {
    writeScreenshot(path, mWindowWidth, mWindowHeight);
    setStatus(strCat("wrote ", std::filesystem::absolute(path).string(), " (", mWindowWidth, "x",
                     mWindowHeight, " window)"),
              false);
}

// The panel's "save": an unwritable path is reported, the viewer goes on.
void Viewer::saveSettings(const std::string& path) {
    try {
        saveRenderBlock(path, mRunner->getSettings());
        setStatus(strCat("wrote the settings (a render block) to ",
                         std::filesystem::absolute(path).string()),
                  false);
    } catch (const std::runtime_error& e) {
        setStatus(e.what(), true);
    }
}

// F12: numbered past the files already there; a folder that cannot take it is reported.
void Viewer::takeNumberedScreenshot() {
    std::string path;
    std::error_code error;
    do {
        path = strCat("ispm_screenshot_", mScreenshotCount++, ".png");
    } while (std::filesystem::exists(path, error));
    try {
        takeScreenshot(path);
    } catch (const std::runtime_error& e) {
        setStatus(e.what(), true);
    }
}

// Shown in the panel's footer and printed (the viewer runs long: said now, not at exit).
void Viewer::setStatus(const std::string& text, bool isError) {
    mStatus = text;
    mStatusIsError = isError;
    std::FILE* out = isError ? stderr : stdout;
    std::fprintf(out, "%s\n", text.c_str());
    std::fflush(out);
}

} // namespace ispm
