// The viewer's two clocks: UI frames (input, panels, the picture shown) at their own rate, and
// rendered frames, drawn in slices between them (FrameRunner::beginFrame/continueFrame). Each UI
// frame gives the render what is left of the UI frame's time after the UI's own work, so a frame
// that takes seconds never holds the window up.
#pragma once

#include <cstddef>
#include <deque>

namespace ispm {

class FramePacer {
  public:
    // The UI frame the pacer aims at: 30 Hz with a tenth to spare for the swap and the events.
    static constexpr double kTargetUiFrameMs = 30.0;
    // The render's share never falls below this, however slow the UI's own work: a frame
    // always gets on (at a fifth of the UI frame's time at worst).
    static constexpr double kMinRenderBudgetMs = 6.0;
    // UI frames the overlay's and print_panel's median looks back over.
    static constexpr size_t kWindow = 32;

    // One UI frame ended: `intervalMs` since the last one ended, of which `renderMs` went to the
    // frame's slice (the rest is the UI's own work: events, panels, the picture, the swap).
    void recordUiFrame(double intervalMs, double renderMs);
    // A UI frame of a slice alone while the window was quiet (not redrawn), `intervalMs` after
    // the last UI frame ended. The window looks at its events between slices, so these bound
    // how long an event waits as drawn UI frames do.
    void recordQuietSlice(double intervalMs);
    // A rendered frame was completed in this UI frame (before its recordUiFrame), `wallMs` after
    // it began.
    void recordRenderFrame(double wallMs);

    // The render's time in the next UI frame.
    double getRenderBudgetMs() const;
    // Median interval between the last kWindow UI frames (0 before two UI frames). Quiet slices
    // end a UI frame too: the window answers an event at the end of the slice it came in.
    double getMedianUiFrameMs() const;
    // The slowest of the last kWindow UI frames (0 before two UI frames).
    double getMaxUiFrameMs() const;
    // Wall time from the start to the end of the last completed rendered frame (0: none yet).
    double getLastRenderFrameMs() const { return mLastRenderFrameMs; }
    // UI frames shown while the last completed rendered frame was drawn.
    int getUiFramesPerRenderFrame() const { return mLastUiFramesPerRender; }

  private:
    std::deque<double> mIntervalsMs;
    double mUiOwnMs = -1.0; // smoothed; < 0: not measured yet
    double mLastRenderFrameMs = 0.0;
    int mUiFramesThisRender = 0;
    bool mRenderCompleted = false;
    int mLastUiFramesPerRender = 0;
};

} // namespace ispm
