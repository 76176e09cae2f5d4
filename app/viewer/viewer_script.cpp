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

#include <cstdio>
#include <filesystem>

namespace ispm {
namespace {

constexpr double kWaitFileSeconds = 60.0; // wait_file: the other side is surely stuck by then
constexpr double kWaitPollSeconds = 0.01;

} // namespace

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
    if (c.kind == ScriptCommand::Kind::SaveSettings) {
        saveRenderBlock(c.path, mRunner->getSettings());
        return;
    }
    const Aov aov = c.text == "display" ? Aov::Display : parseAov(c.text, c.where);
    writeImage(c.path, readTextureImage(mRunner->getAov(aov)));
    std::printf("wrote %s (%s)\n", c.path.c_str(), c.text.c_str());
    std::fflush(stdout);
}

} // namespace ispm
