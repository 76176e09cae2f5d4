// FramePacer: the render's share of a UI frame is what the UI's own work leaves of the target
// (never below the floor), the UI's cost is smoothed, and the rates the overlay shows count the
// UI frames, quiet ones included.
#include "viewer/frame_pacer.h"

#include <gtest/gtest.h>

namespace ispm {
namespace {

TEST(FramePacer, RenderGetsWhatTheUiLeaves) {
    FramePacer pacer;
    // Nothing measured: the whole UI frame.
    EXPECT_DOUBLE_EQ(pacer.getRenderBudgetMs(), FramePacer::kTargetUiFrameMs);
    // A UI that costs 10 ms a frame (30 ms frames of which 20 rendered) leaves 20 ms.
    for (int i = 0; i < 50; ++i)
        pacer.recordUiFrame(30.0, 20.0);
    EXPECT_NEAR(pacer.getRenderBudgetMs(), FramePacer::kTargetUiFrameMs - 10.0, 1e-9);
    // One slow UI frame moves the budget by a fifth of its excess, not all of it.
    pacer.recordUiFrame(70.0, 20.0);
    EXPECT_NEAR(pacer.getRenderBudgetMs(), FramePacer::kTargetUiFrameMs - 18.0, 1e-9);
    // A UI slower than the target still leaves the floor to the render.
    for (int i = 0; i < 50; ++i)
        pacer.recordUiFrame(60.0, 0.0);
    EXPECT_DOUBLE_EQ(pacer.getRenderBudgetMs(), FramePacer::kMinRenderBudgetMs);
}

TEST(FramePacer, CountsUiFramesPerRenderedFrameAndTheirMedian) {
    FramePacer pacer;
    EXPECT_EQ(pacer.getMedianUiFrameMs(), 0.0);
    for (int i = 0; i < 9; ++i)
        pacer.recordUiFrame(25.0, 15.0);
    pacer.recordQuietSlice(20.0); // quiet slices answer events as UI frames do
    pacer.recordRenderFrame(400.0);
    pacer.recordUiFrame(500.0, 15.0); // the frame it completed in, counted with it
    EXPECT_EQ(pacer.getUiFramesPerRenderFrame(), 10);
    EXPECT_DOUBLE_EQ(pacer.getLastRenderFrameMs(), 400.0);
    EXPECT_DOUBLE_EQ(pacer.getMedianUiFrameMs(), 25.0);
    EXPECT_DOUBLE_EQ(pacer.getMaxUiFrameMs(), 500.0);
    // The window looks back kWindow UI frames.
    for (size_t i = 0; i < FramePacer::kWindow; ++i)
        pacer.recordUiFrame(10.0, 5.0);
    EXPECT_DOUBLE_EQ(pacer.getMaxUiFrameMs(), 10.0);
}

} // namespace
} // namespace ispm
