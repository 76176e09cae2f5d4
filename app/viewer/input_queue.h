// The window's input as events in the order they came (GLFW callbacks, or a script standing in
// for them), handed out a frame at a time so that a per-frame reader loses none: ImGui 1.86 reads
// one mouse position and one button state per frame, so a click and the move after it must reach
// it in different frames. Also which move keys the fly camera sees. No GLFW, no ImGui: tests
// drive it directly.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <set>
#include <vector>

namespace ispm {

inline constexpr int kMouseButtonCount = 5; // ImGui 1.86's io.MouseDown[]
inline constexpr int kMouseLeft = 0;        // GLFW_MOUSE_BUTTON_LEFT

struct InputEvent {
    enum class Kind { Move, Button, Key, Char, Scroll };
    Kind kind = Kind::Move;
    glm::dvec2 cursor{0.0}; // Move: window pixels, y down
    int code = 0;           // Button: GLFW button; Key: GLFW key; Char: Unicode code point
    bool down = false;      // Button, Key: pressed (true) or released
    int mods = 0;           // Key: GLFW modifier bits (GLFW_MOD_CONTROL ...)
    double scroll = 0.0;    // Scroll: vertical steps

    static InputEvent move(glm::dvec2 cursor) { return {.kind = Kind::Move, .cursor = cursor}; }
    static InputEvent button(int code, bool down) {
        return {.kind = Kind::Button, .code = code, .down = down};
    }
    static InputEvent key(int code, bool down, int mods = 0) {
        return {.kind = Kind::Key, .code = code, .down = down, .mods = mods};
    }
    static InputEvent character(unsigned int c) {
        return {.kind = Kind::Char, .code = static_cast<int>(c)};
    }
    static InputEvent wheel(double steps) { return {.kind = Kind::Scroll, .scroll = steps}; }
};

// One frame's share of the queue: its events in order, and the pointer's state after them.
struct FrameInput {
    std::vector<InputEvent> events;
    glm::dvec2 cursor{0.0};
    std::array<bool, kMouseButtonCount> buttons{};
};

class InputQueue {
  public:
    void push(const InputEvent& event) {
        mPending.push_back(event);
        ++mPushedCount;
    }
    // Where the pointer is before any event (the window's cursor at start-up).
    void setCursor(glm::dvec2 cursor) { mCursor = cursor; }
    // The next frame's events: in order, stopping before one that a per-frame reader would see
    // merged with an earlier one of the frame: a second change of a mouse button, a move, key
    // or character after a button changed (the click lands where it was made, and ImGui knows
    // whether it focused a text field before the keys arrive), a second change of one key.
    FrameInput takeFrame();
    bool isEmpty() const { return mPending.empty(); }
    // Events pushed and handed out so far: whether a given event has reached a frame yet.
    uint64_t getPushedCount() const { return mPushedCount; }
    uint64_t getTakenCount() const { return mPushedCount - mPending.size(); }

  private:
    std::deque<InputEvent> mPending;
    glm::dvec2 mCursor{0.0};
    std::array<bool, kMouseButtonCount> mButtons{};
    uint64_t mPushedCount = 0;
};

// The keys held for the fly camera. A key pressed while ImGui wants the keyboard (a text field
// has the focus) never moves the camera, not even after the field lets go; while it wants the
// keyboard no key moves the camera.
class CameraKeys {
  public:
    void apply(const FrameInput& input, bool imguiWantsKeyboard);
    bool isHeld(int key) const { return mHeld.count(key) > 0; }

  private:
    std::set<int> mHeld;
};

} // namespace ispm
