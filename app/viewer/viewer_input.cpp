// ViewerInput: GLFW's callbacks into the queue, the queue's events into the camera's input and the
// viewer's keys, and a script's clicks and keys turned into the events a user would make.
#include "viewer/viewer_input.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/gl.h" // before GLFW: glad's header must come first

#include <GLFW/glfw3.h>

#include <array>
#include <cctype>
#include <filesystem>

namespace ispm {
namespace {

constexpr double kWaitFileSeconds = 60.0; // wait_file: the other side is surely stuck by then
constexpr double kWaitPollSeconds = 0.01;

struct KeyAxis {
    int key;
    char name;
    glm::vec3 move; // right, up, forward
};

constexpr std::array<KeyAxis, 6> kMoveKeys = {{
    {GLFW_KEY_W, 'W', {0, 0, 1}},
    {GLFW_KEY_S, 'S', {0, 0, -1}},
    {GLFW_KEY_D, 'D', {1, 0, 0}},
    {GLFW_KEY_A, 'A', {-1, 0, 0}},
    {GLFW_KEY_E, 'E', {0, 1, 0}},
    {GLFW_KEY_Q, 'Q', {0, -1, 0}},
}};

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

float computeSceneSize(const Scene& scene) {
    return glm::length(scene.computeWorldBounds().getExtent());
}

} // namespace

ViewerInput::ViewerInput(GLFWwindow* window, const Scene& scene, std::vector<ScriptCommand> script)
    : mFly(scene.camera, computeSceneSize(scene)), mScriptSize(script.size()),
      mScript(std::move(script)) {
    installCallbacks(window);
    glfwGetCursorPos(window, &mLastCursor.x, &mLastCursor.y);
    mQueue.setCursor(mLastCursor);
}

ViewerInput& ViewerInput::getInput(GLFWwindow* window) {
    return *static_cast<ViewerInput*>(glfwGetWindowUserPointer(window));
}

// Events, not polled state: a click, a key tapped or a character typed between two slow frames
// (a software renderer) reaches ImGui and the camera in its order (InputQueue).
void ViewerInput::installCallbacks(GLFWwindow* window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        getInput(w).mQueue.push(InputEvent::move({x, y}));
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
        (void)mods;
        getInput(w).mQueue.push(InputEvent::button(button, action == GLFW_PRESS));
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double dx, double dy) {
        (void)dx;
        getInput(w).mQueue.push(InputEvent::wheel(dy));
    });
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        (void)scancode;
        if (action == GLFW_REPEAT) return; // held keys stay down until released
        getInput(w).mQueue.push(InputEvent::key(key, action == GLFW_PRESS, mods));
    });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int c) {
        getInput(w).mQueue.push(InputEvent::character(c));
    });
}

ViewerKeys ViewerInput::readKeys(const FrameInput& input, bool typing) {
    ViewerKeys keys;
    for (const InputEvent& e : input.events) {
        if (e.kind != InputEvent::Kind::Key || !e.down) continue;
        if (e.code == GLFW_KEY_F12) keys.screenshot = true;
        if (e.code == GLFW_KEY_F5) keys.reloadShaders = true;
        if (e.code == GLFW_KEY_F1 && !typing) keys.toggleHelp = !keys.toggleHelp;
        if (e.code == GLFW_KEY_F2 && !typing) keys.toggleFrameRate = !keys.toggleFrameRate;
        if (e.code == GLFW_KEY_Q && (e.mods & GLFW_MOD_CONTROL) != 0 && !typing) keys.quit = true;
    }
    return keys;
}

// ImGui has seen this frame's events (beginFrame) before the camera: its capture flags are
// those of this frame, not the last one.
CameraInput ViewerInput::readCamera(const FrameInput& in, bool panelHasMouse, bool typing) {
    CameraInput input;
    for (const InputEvent& e : in.events) {
        // A drag belongs to the camera only if it started outside the panels.
        if (e.kind == InputEvent::Kind::Button && e.code == kMouseLeft) {
            mDragging = e.down && !panelHasMouse;
        }
        if (e.kind == InputEvent::Kind::Move) {
            if (mDragging) input.dragPx += glm::vec2(e.cursor - mLastCursor);
            mLastCursor = e.cursor;
        }
        if (e.kind == InputEvent::Kind::Scroll && !panelHasMouse) {
            input.wheel += static_cast<float>(e.scroll);
        }
    }
    mCameraKeys.apply(in, typing);
    for (const KeyAxis& k : kMoveKeys) {
        if (mCameraKeys.isHeld(k.key)) input.move += k.move;
    }
    return input;
}

bool ViewerInput::isIdle() const {
    if (!mQueue.isEmpty() || mDragging) return false;
    for (const KeyAxis& k : kMoveKeys) {
        if (mCameraKeys.isHeld(k.key)) return false; // the camera flies on every UI frame
    }
    return true;
}

void ViewerInput::resetFly(const Scene& scene) {
    mFly = FlyCamera(scene.camera, computeSceneSize(scene));
}

bool ViewerInput::finishScript() {
    if (mScriptDone || mScriptSize == 0 || !mScript.isFinished() || !isScriptInputSeen()) {
        return false;
    }
    mScriptDone = true;
    return true;
}

void ViewerInput::pushScriptInput(const ScriptCommand& c, const ItemRects& items) {
    using Kind = ScriptCommand::Kind;
    glm::dvec2 at(c.x, c.y);
    if (c.kind == Kind::ClickItem) {
        const auto item = items.find(c.text);
        if (item == items.end()) {
            throw InputError(strCat(c.where, ": no panel item '", c.text,
                                    "' was drawn (see input_script.h for the names)"));
        }
        at = glm::dvec2((item->second.min + item->second.max) * 0.5f);
    }
    switch (c.kind) {
    case Kind::Click:
    case Kind::ClickItem:
        mQueue.push(InputEvent::move(at));
        mQueue.push(InputEvent::button(kMouseLeft, true));
        mQueue.push(InputEvent::button(kMouseLeft, false));
        break;
    case Kind::MouseMove:
        mQueue.push(InputEvent::move(at));
        break;
    case Kind::Press: {
        const int key = findGlfwKey(c.text);
        const bool ctrl = c.option == "ctrl";
        const int mods = ctrl ? GLFW_MOD_CONTROL : 0;
        if (ctrl) mQueue.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, true, mods));
        mQueue.push(InputEvent::key(key, true, mods));
        mQueue.push(InputEvent::key(key, false, mods));
        if (ctrl) mQueue.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, false));
        break;
    }
    case Kind::Type:
        for (char ch : c.text) {
            const int key = findTypingKey(ch);
            mQueue.push(InputEvent::key(key, true));
            mQueue.push(InputEvent::character(static_cast<unsigned char>(ch)));
            mQueue.push(InputEvent::key(key, false));
        }
        break;
    default:
        break;
    }
    mScriptInputEnd = mQueue.getPushedCount();
}

void ViewerInput::addScriptCamera(const ScriptCommand& c, CameraInput& input) {
    using Kind = ScriptCommand::Kind;
    if (c.kind == Kind::Key) {
        for (const KeyAxis& k : kMoveKeys) {
            if (k.name == c.text[0]) input.move += k.move;
        }
    }
    if (c.kind == Kind::MouseDrag) input.dragPx += glm::vec2(c.x, c.y);
    if (c.kind == Kind::Wheel) input.wheel += c.x;
}

void ViewerInput::waitForFile(const ScriptCommand& c) {
    const double start = glfwGetTime();
    while (!std::filesystem::exists(c.path)) {
        if (glfwGetTime() - start > kWaitFileSeconds) {
            throw InputError(strCat(c.where, ": gave up waiting for ", c.path));
        }
        glfwWaitEventsTimeout(kWaitPollSeconds);
    }
}

} // namespace ispm
