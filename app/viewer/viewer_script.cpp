// The viewer's scripted input (`ispm view --script`): each command steers the camera, the settings,
// the views or the reference as a user would, and the outputs (images, metrics, screenshots,
// settings) are written after the frame they describe.
#include "viewer/viewer_app.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/gl.h"
#include "image/image_io.h"
#include "render/readback.h"
#include "scene/scene_loader.h"

#include <GLFW/glfw3.h>

#include <cctype>
#include <cstdio>
#include <filesystem>

namespace ispm {
namespace {

constexpr double kWaitFileSeconds = 60.0; // wait_file: the other side is surely stuck by then
constexpr double kWaitPollSeconds = 0.01;

// GLFW's key for a name isScriptKeyName accepts (letters and digits are their ASCII codes).
int findGlfwKey(const std::string& name) {
    if (name.size() == 1) return static_cast<unsigned char>(name[0]); // 'A'..'Z', '0'..'9'
    if (name == "ESCAPE") return GLFW_KEY_ESCAPE;
    if (name == "ENTER") return GLFW_KEY_ENTER;
    if (name == "TAB") return GLFW_KEY_TAB;
    if (name == "BACKSPACE") return GLFW_KEY_BACKSPACE;
    return GLFW_KEY_F1 + std::stoi(name.substr(1)) - 1;
}

// The key that types `c` on a US layout ('_' is Shift and minus; Shift is left out: ImGui
// takes the character from the char event).
int findTypingKey(char c) {
    if (std::isalpha(static_cast<unsigned char>(c)) != 0) {
        return std::toupper(static_cast<unsigned char>(c));
    }
    if (std::isdigit(static_cast<unsigned char>(c)) != 0) return c;
    switch (c) {
    case ' ':
        return GLFW_KEY_SPACE;
    case '.':
        return GLFW_KEY_PERIOD;
    case '/':
        return GLFW_KEY_SLASH;
    default:
        return GLFW_KEY_MINUS; // '-' and '_'
    }
}

} // namespace

// Click, move, press and type: window events into the queue, in the order GLFW gives them.
void Viewer::pushScriptInput(const ScriptCommand& c) {
    using Kind = ScriptCommand::Kind;
    glm::dvec2 at(c.x, c.y);
    if (c.kind == Kind::ClickItem) {
        const auto item = mItems.find(c.text);
        if (item == mItems.end()) {
            throw InputError(strCat(c.where, ": no panel item '", c.text,
                                    "' was drawn (see input_script.h for the names)"));
        }
        at = glm::dvec2((item->second.min + item->second.max) * 0.5f);
    }
    switch (c.kind) {
    case Kind::Click:
    case Kind::ClickItem:
        mInput.push(InputEvent::move(at));
        mInput.push(InputEvent::button(kMouseLeft, true));
        mInput.push(InputEvent::button(kMouseLeft, false));
        break;
    case Kind::MouseMove:
        mInput.push(InputEvent::move(at));
        break;
    case Kind::Press: {
        const int key = findGlfwKey(c.text);
        const bool ctrl = c.option == "ctrl";
        const int mods = ctrl ? GLFW_MOD_CONTROL : 0;
        if (ctrl) mInput.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, true, mods));
        mInput.push(InputEvent::key(key, true, mods));
        mInput.push(InputEvent::key(key, false, mods));
        if (ctrl) mInput.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, false));
        break;
    }
    case Kind::Type:
        for (char ch : c.text) {
            const int key = findTypingKey(ch);
            mInput.push(InputEvent::key(key, true));
            mInput.push(InputEvent::character(static_cast<unsigned char>(ch)));
            mInput.push(InputEvent::key(key, false));
        }
        break;
    default:
        break;
    }
    mScriptInputEnd = mInput.getPushedCount();
}

// What the panel shows, for scripts and tests: its message lines and the Stats frame time.
void Viewer::printPanel() {
    std::printf("panel status: %s\n", mStatus.c_str());
    std::printf("panel title: %s\n", mContext.getTitle().c_str());
    std::printf("panel metrics: %s\n", mReference.getMetricsText().c_str());
    std::printf("panel reference: %s\n", mReference.getStatus().c_str());
    const glm::vec3& p = mScene.camera.position;
    std::printf("panel camera: %.6f %.6f %.6f\n", static_cast<double>(p.x),
                static_cast<double>(p.y), static_cast<double>(p.z));
    std::printf("panel frame ms: %.6f\n", mTimings.getLastTotalMs());
    // The clocks of the window: rendered frames in wall time (their slices and the UI frames
    // between them) and the UI frames' median interval.
    std::printf("panel frame wall ms: %.6f\n", mPacer.getLastRenderFrameMs());
    std::printf("panel ui frame ms: %.6f\n", mPacer.getMedianUiFrameMs());
    std::printf("panel ui frame max ms: %.6f\n", mPacer.getMaxUiFrameMs());
    std::printf("panel ui frames per frame: %d\n", mPacer.getUiFramesPerRenderFrame());
    for (const PassTiming& t : mTimings.getLast())
        std::printf("panel pass ms: %s = %.6f\n", t.name.c_str(), t.ms);
    std::printf("panel view stops: %s\n",
                usesViewStops(mViews[static_cast<size_t>(mViewIndex)]) ? "on" : "off");
    std::fflush(stdout);
}

void Viewer::runScriptCommand(const ScriptCommand& c, CameraInput& input,
                              std::vector<const ScriptCommand*>& afterFrame) {
    using Kind = ScriptCommand::Kind;
    switch (c.kind) {
    case Kind::Key:
        for (const KeyAxis& k : kMoveKeys) {
            if (k.name == c.text[0]) input.move += k.move;
        }
        break;
    case Kind::MouseDrag:
        input.dragPx += glm::vec2(c.x, c.y);
        break;
    case Kind::Wheel:
        input.wheel += c.x;
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
    case Kind::View: {
        const int index = findDebugView(mViews, c.text);
        if (index < 0) throw InputError(strCat(c.where, ": unknown view '", c.text, "'"));
        mViewIndex = index;
        break;
    }
    case Kind::Points:
        for (size_t i = 0; i < kPhotonPointsNames.size(); ++i) {
            if (c.text == kPhotonPointsNames[i]) mPoints = static_cast<PhotonPoints>(i);
        }
        for (size_t i = 0; i < kPhotonColourNames.size(); ++i) {
            if (c.option == kPhotonColourNames[i]) mPointsColour = static_cast<PhotonColour>(i);
        }
        break;
    case Kind::ResetCamera:
        mFly.reset(mScene.camera);
        break;
    case Kind::ReloadShaders:
        reloadShaders();
        break;
    case Kind::WaitFile:
        waitForFile(c);
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
        afterFrame.push_back(&c);
        break;
    case Kind::PrintPanel:
        afterFrame.push_back(&c);
        break;
    case Kind::Click:
    case Kind::ClickItem:
    case Kind::MouseMove:
    case Kind::Press:
    case Kind::Type:
        pushScriptInput(c);
        break;
    case Kind::Frames:
        break;
    }
}

// Blocks the frame loop (the window stays responsive) until another process created the file.
void Viewer::waitForFile(const ScriptCommand& c) {
    const double start = glfwGetTime();
    while (!std::filesystem::exists(c.path)) {
        if (glfwGetTime() - start > kWaitFileSeconds) {
            throw InputError(strCat(c.where, ": gave up waiting for ", c.path));
        }
        glfwWaitEventsTimeout(kWaitPollSeconds);
    }
}

void Viewer::writeScriptOutput(const ScriptCommand& c) {
    if (c.kind == ScriptCommand::Kind::Screenshot) {
        takeScreenshot(c.path);
        return;
    }
    if (c.kind == ScriptCommand::Kind::ComputeMetrics) {
        std::printf("reference: %s\n", mReference.computeMetrics(*mRunner).c_str());
        std::fflush(stdout);
        return;
    }
    if (c.kind == ScriptCommand::Kind::PrintPanel) {
        printPanel();
        return;
    }
    if (c.kind == ScriptCommand::Kind::SaveSettings) {
        saveRenderBlock(c.path, mRunner->getSettings()); // a script's bad path ends the run
        setStatus(strCat("wrote the settings (a render block) to ",
                         std::filesystem::absolute(c.path).string()),
                  false);
        return;
    }
    const Aov aov = c.text == "display" ? Aov::Display : parseAov(c.text, c.where);
    writeImage(c.path, readTextureImage(mRunner->getAov(aov)));
    std::printf("wrote %s (%s)\n", c.path.c_str(), c.text.c_str());
    std::fflush(stdout);
}

} // namespace ispm
