// The viewer's files and its message line: screenshots (F12, --screenshot, scripts), AOV images
// and the settings' render block written, and the footer line under the panels that says what
// was written, and where (or why not).
#pragma once

#include "render/frame.h"
#include "settings/settings.h"

#include <string>

namespace ispm {

class ViewerOutput {
  public:
    // Shown in the panel's footer and printed (the viewer runs long: said now, not at exit).
    void setStatus(const std::string& text, bool isError);
    const std::string& getStatus() const { return mStatus; }

    // The window as it was last drawn; throws when the file cannot be written.
    void takeScreenshot(const std::string& path, int windowWidth, int windowHeight);
    // F12: numbered past the files already there; a folder that cannot take it is reported.
    void takeNumberedScreenshot(int windowWidth, int windowHeight);
    // The panel's "save": an unwritable path is reported, the viewer goes on.
    void saveSettings(const std::string& path, const Settings& settings);
    // A script's save_settings: an unwritable path throws (it ends the run).
    void writeSettings(const std::string& path, const Settings& settings);
    // A script's write_aov: `aovName` is "display" or an AOV's name (`where` names the script
    // line for a bad one).
    static void writeAov(const std::string& path, const std::string& aovName,
                         const std::string& where, const FrameRunner& runner);

    // The message line's wrapped height, a few lines at most (a longer one scrolls), with the
    // separator above it; 0 without a message. Inside the panel's ImGui window.
    float computeFooterHeight() const;
    void drawFooter() const;

  private:
    std::string mStatus; // the panel's message line (a file written, a path refused ...)
    bool mStatusIsError = false;
    int mScreenshotCount = 0;
};

// A message wrapped in the message line's colours (red for an error), wherever a panel says what
// went wrong or right: the line itself, the shaders' reload, a missing reference.
void drawMessageText(const std::string& text, bool isError);

} // namespace ispm
