// The viewer's scripted input (`ispm view --script`): each command steers the camera, the settings,
// the views or the reference as a user would, and the outputs (images, metrics, screenshots,
// settings) are written after the frame they describe.
#include "viewer/viewer_app.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "viewer/settings_panel.h"

#include <cstdio>

namespace ispm {

// At the start of a rendered frame. A script's clicks and keys go through the queue as the
// window's do; the script goes on once they have all reached a frame (the user's own events do
// not hold it up).
void Viewer::advanceScript(CameraInput& input, std::vector<const ScriptCommand*>& afterFrame) {
    // Said the frame after the last command's, so that its outputs saw the panel before.
    const bool scriptInputSeen = mInput.isScriptInputSeen();
    if (mInput.finishScript()) {
        mOutput.setStatus(strCat("script finished (", mInput.getScriptSize(), " commands)"), false);
    }
    if (!scriptInputSeen) return;
    for (const ScriptCommand* c : mInput.advanceScript())
        runScriptCommand(*c, input, afterFrame);
}

void Viewer::runScriptCommand(const ScriptCommand& c, CameraInput& input,
                              std::vector<const ScriptCommand*>& afterFrame) {
    using Kind = ScriptCommand::Kind;
    switch (c.kind) {
    case Kind::Key:
    case Kind::MouseDrag:
    case Kind::Wheel:
        ViewerInput::addScriptCamera(c, input);
        break;
    case Kind::Set: {
        const std::string name = c.text.substr(0, c.text.find('='));
        if (isWindowSetting(name)) {
            throw InputError(
                strCat(c.where, ": '", name, "' follows the window; use --width/--height"));
        }
        Settings next = mRunner->getSettings();
        next.setFromString(c.text, c.where);
        applySettings(next);
        break;
    }
    case Kind::View:
        if (!mPanels.selectView(c.text)) {
            throw InputError(strCat(c.where, ": unknown view '", c.text, "'"));
        }
        break;
    case Kind::Points:
        mPanels.selectPoints(c.text, c.option);
        break;
    case Kind::ResetCamera:
        mInput.getFly().reset(mScene.camera);
        break;
    case Kind::ReloadShaders:
        reloadShaders();
        break;
    case Kind::WaitFile:
        ViewerInput::waitForFile(c);
        break;
    case Kind::LoadScene:
        mPendingScenePath = c.path; // as the picker: switched at the start of the next frame
        break;
    case Kind::LoadReference:
        mReference.load(c.path);
        break;
    case Kind::RenderReference:
        mReference.setRendering(c.text == "on");
        break;
    case Kind::ComputeMetrics:
    case Kind::WriteAov:
    case Kind::Screenshot:
    case Kind::SaveSettings:
    case Kind::PrintPanel:
        afterFrame.push_back(&c);
        break;
    case Kind::Click:
    case Kind::ClickItem:
    case Kind::MouseMove:
    case Kind::Press:
    case Kind::Type:
        mInput.pushScriptInput(c, mPanels.getItems());
        break;
    case Kind::Frames:
        break;
    }
}

void Viewer::writeScriptOutput(const ScriptCommand& c) {
    if (c.kind == ScriptCommand::Kind::Screenshot) {
        mOutput.takeScreenshot(c.path, mWindowWidth, mWindowHeight);
        return;
    }
    if (c.kind == ScriptCommand::Kind::ComputeMetrics) {
        std::printf("reference: %s\n", mReference.computeMetrics(*mRunner).c_str());
        std::fflush(stdout);
        return;
    }
    if (c.kind == ScriptCommand::Kind::PrintPanel) {
        mPanels.print(makePanelContext());
        return;
    }
    if (c.kind == ScriptCommand::Kind::SaveSettings) {
        mOutput.writeSettings(c.path, mRunner->getSettings()); // a bad path ends the run
        return;
    }
    ViewerOutput::writeAov(c.path, c.text, c.where, *mRunner);
}

} // namespace ispm
