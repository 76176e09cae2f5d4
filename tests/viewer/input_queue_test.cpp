// The viewer's event queue and camera keys (no window): a click reaches ImGui where it was made
// even when the pointer moved on before the next frame, keys typed after a click wait until ImGui
// has seen it, and keys typed into a text field never move the camera.
#include "viewer/input_queue.h"
#include "viewer/viewer_app.h"

#include <gtest/gtest.h>

namespace ispm::test {
namespace {

constexpr int kKeyW = 'W'; // GLFW key codes of letters are their ASCII capitals

TEST(InputQueue, ClickThenMoveReachesTheFramesInOrder) {
    InputQueue queue;
    queue.setCursor({1.0, 1.0});
    const glm::dvec2 button(300.0, 40.0);
    const glm::dvec2 away(5.0, 5.0);
    // All of it arrived while one slow frame rendered.
    queue.push(InputEvent::move(button));
    queue.push(InputEvent::button(kMouseLeft, true));
    queue.push(InputEvent::button(kMouseLeft, false));
    queue.push(InputEvent::move(away));
    const FrameInput press = queue.takeFrame();
    EXPECT_EQ(press.cursor, button);
    EXPECT_TRUE(press.buttons[kMouseLeft]);
    const FrameInput release = queue.takeFrame();
    EXPECT_EQ(release.cursor, button); // released over the button: ImGui's click
    EXPECT_FALSE(release.buttons[kMouseLeft]);
    EXPECT_EQ(queue.getTakenCount(), 3u);
    const FrameInput moved = queue.takeFrame();
    EXPECT_EQ(moved.cursor, away);
    EXPECT_TRUE(queue.isEmpty());
    EXPECT_EQ(queue.getTakenCount(), queue.getPushedCount());
    // An idle frame keeps the last state.
    EXPECT_EQ(queue.takeFrame().cursor, away);
}

TEST(InputQueue, KeysWaitForAClickAndOneKeyChangesOnceAFrame) {
    InputQueue queue;
    queue.push(InputEvent::button(kMouseLeft, true));
    queue.push(InputEvent::button(kMouseLeft, false));
    queue.push(InputEvent::key(kKeyW, true));
    queue.push(InputEvent::character('w'));
    queue.push(InputEvent::key(kKeyW, false));
    queue.push(InputEvent::wheel(2.0));
    std::vector<size_t> sizes;
    while (!queue.isEmpty())
        sizes.push_back(queue.takeFrame().events.size());
    // press | release | W down + 'w' | W up + wheel (a wheel step splits nothing).
    const std::vector<size_t> expected = {1, 1, 2, 2};
    EXPECT_EQ(sizes, expected);
}

TEST(CameraKeys, KeysTypedIntoAFieldNeverMoveTheCamera) {
    CameraKeys keys;
    const auto frameOf = [](InputEvent e) { return FrameInput{.events = {e}}; };
    // Typed while a text field has the keyboard: W goes down and up ...
    keys.apply(frameOf(InputEvent::key(kKeyW, true)), true);
    EXPECT_FALSE(keys.isHeld(kKeyW));
    keys.apply(frameOf(InputEvent::key(kKeyW, false)), true);
    // ... and once the field lets go, nothing comes back (sticky keys did bring it back).
    keys.apply(FrameInput{}, false);
    EXPECT_FALSE(keys.isHeld(kKeyW));
    // Outside a field W moves until released; a field taking the keyboard stops it.
    keys.apply(frameOf(InputEvent::key(kKeyW, true)), false);
    EXPECT_TRUE(keys.isHeld(kKeyW));
    keys.apply(FrameInput{}, false);
    EXPECT_TRUE(keys.isHeld(kKeyW));
    keys.apply(FrameInput{}, true);
    EXPECT_FALSE(keys.isHeld(kKeyW));
}

TEST(ViewStops, ApplyToEveryViewButTheToneMappedDisplay) {
    const std::vector<DebugView> views = buildDebugViews();
    ASSERT_FALSE(views.empty());
    for (const DebugView& view : views) {
        EXPECT_EQ(usesViewStops(view), view.name != "display") << view.name;
    }
}

TEST(TimingHistory, FrameRowAddsUpEveryTimedPart) {
    TimingHistory history;
    history.record({{"gbuffer", 2.0}, {"splat", 5.0}, {"reference (path tracer)", 10.0}});
    EXPECT_DOUBLE_EQ(history.getLastTotalMs(), 17.0);
    EXPECT_FLOAT_EQ(history.getFrameTotals().back(), 17.0f);
}

} // namespace
} // namespace ispm::test
