// Splitting the event queue into frames, and the camera's held keys.
#include "viewer/input_queue.h"

namespace ispm {

FrameInput InputQueue::takeFrame() {
    FrameInput frame;
    bool buttonChanged = false;
    std::set<int> keysChanged;
    while (!mPending.empty()) {
        const InputEvent& e = mPending.front();
        const bool afterClick = buttonChanged && e.kind != InputEvent::Kind::Scroll;
        if (afterClick) break;
        if (e.kind == InputEvent::Kind::Key && !keysChanged.insert(e.code).second) break;
        if (e.kind == InputEvent::Kind::Move) mCursor = e.cursor;
        if (e.kind == InputEvent::Kind::Button && e.code >= 0 && e.code < kMouseButtonCount) {
            buttonChanged = mButtons[static_cast<size_t>(e.code)] != e.down;
            mButtons[static_cast<size_t>(e.code)] = e.down;
        }
        frame.events.push_back(e);
        mPending.pop_front();
    }
    frame.cursor = mCursor;
    frame.buttons = mButtons;
    return frame;
}

void CameraKeys::apply(const FrameInput& input, bool imguiWantsKeyboard) {
    if (imguiWantsKeyboard) mHeld.clear();
    for (const InputEvent& e : input.events) {
        if (e.kind != InputEvent::Kind::Key) continue;
        if (!e.down) {
            mHeld.erase(e.code);
        } else if (!imguiWantsKeyboard) {
            mHeld.insert(e.code);
        }
    }
}

} // namespace ispm
