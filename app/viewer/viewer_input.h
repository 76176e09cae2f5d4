// The viewer's input: the window's events queued in their order (GLFW callbacks, and a script's
// clicks and keys standing in for them), the fly camera they steer, and the script that drives a
// run frame by frame (`ispm view --script`).
#pragma once

#include "scene/scene.h"
#include "viewer/fly_camera.h"
#include "viewer/input_queue.h"
#include "viewer/input_script.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

struct GLFWwindow;

namespace ispm {

// A widget's place on the panel as last drawn, for scripts that click it (`click_item`).
struct ItemRect {
    glm::vec2 min{0.0f};
    glm::vec2 max{0.0f};
};
using ItemRects = std::map<std::string, ItemRect>;

// The viewer's own keys pressed during one frame: what F12, F5 and Ctrl+Q ask for, and whether
// F1 and F2 flip their window (once per press).
struct ViewerKeys {
    bool screenshot = false;      // F12
    bool reloadShaders = false;   // F5
    bool toggleHelp = false;      // F1
    bool toggleFrameRate = false; // F2
    bool quit = false;            // Ctrl+Q
};

class ViewerInput {
  public:
    // Installs the window's event callbacks, which reach this object through the window's user
    // pointer: it must not move, so it cannot be copied.
    ViewerInput(GLFWwindow* window, const Scene& scene, std::vector<ScriptCommand> script);
    ViewerInput(const ViewerInput&) = delete;
    ViewerInput& operator=(const ViewerInput&) = delete;

    // The next frame's share of the queued events (InputQueue::takeFrame).
    FrameInput takeFrame() { return mQueue.takeFrame(); }
    // F5 and F12 act whatever has the keyboard; F1, F2 and Ctrl+Q unless a text field has it
    // (`typing`).
    static ViewerKeys readKeys(const FrameInput& input, bool typing);
    // The camera's share of this frame's events: a drag that started outside the panels, the
    // wheel outside them, the move keys held (none while a text field has the keyboard).
    CameraInput readCamera(const FrameInput& input, bool panelHasMouse, bool typing);
    // Whether no event waits and nothing (a drag, a held move key) moves the camera.
    bool isIdle() const;

    FlyCamera& getFly() { return mFly; }
    const FlyCamera& getFly() const { return mFly; }
    // Another scene: the camera flies from its home at a speed that suits its size.
    void resetFly(const Scene& scene);

    // The script's commands for the next frame (ScriptPlayer::advanceFrame). The caller goes on
    // only once all the script's events reached a frame (isScriptInputSeen): the user's own
    // events do not hold it up.
    std::vector<const ScriptCommand*> advanceScript() { return mScript.advanceFrame(); }
    bool isScriptInputSeen() const { return mQueue.getTakenCount() >= mScriptInputEnd; }
    // True once: when a script was given, is finished and its events reached a frame.
    bool finishScript();
    size_t getScriptSize() const { return mScriptSize; }
    // Click, move, press and type: window events into the queue, in the order GLFW gives them.
    // `click_item` clicks the middle of the item as last drawn; throws InputError for an item
    // that was not drawn.
    void pushScriptInput(const ScriptCommand& c, const ItemRects& items);
    // key, mouse_drag and wheel: the scripted share of the camera's input.
    static void addScriptCamera(const ScriptCommand& c, CameraInput& input);
    // wait_file: blocks the frame loop (the window stays responsive) until another process
    // created the file; throws InputError after a minute.
    static void waitForFile(const ScriptCommand& c);

  private:
    static ViewerInput& getInput(GLFWwindow* window);
    void installCallbacks(GLFWwindow* window);

    InputQueue mQueue; // the window's events (and a script's stand-ins), in order
    CameraKeys mCameraKeys;
    glm::dvec2 mLastCursor{0.0};
    bool mDragging = false;
    FlyCamera mFly;
    size_t mScriptSize = 0; // before mScript, which takes the commands
    ScriptPlayer mScript;
    uint64_t mScriptInputEnd = 0; // the queue's count after the script's last event
    bool mScriptDone = false;     // said so once
};

} // namespace ispm
