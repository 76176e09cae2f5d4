// FramePacer: the render's share of each UI frame, and the UI frame rate the overlay shows.
#include "viewer/frame_pacer.h"

#include <algorithm>
#include <vector>

namespace ispm {
namespace {

// The UI's own time is smoothed over a few frames: one slow panel (a combo box opening, a
// screenshot written) does not starve the render, and a lasting change is followed in ~5 frames.
constexpr double kUiCostWeight = 0.2;

} // namespace

void FramePacer::recordUiFrame(double intervalMs, double renderMs) {
    const double ownMs = std::max(0.0, intervalMs - renderMs);
    mUiOwnMs = mUiOwnMs < 0.0 ? ownMs : mUiOwnMs + kUiCostWeight * (ownMs - mUiOwnMs);
    mIntervalsMs.push_back(intervalMs);
    if (mIntervalsMs.size() > kWindow) mIntervalsMs.pop_front();
    ++mUiFramesThisRender;
    if (mRenderCompleted) {
        mLastUiFramesPerRender = mUiFramesThisRender;
        mUiFramesThisRender = 0;
        mRenderCompleted = false;
    }
}

void FramePacer::recordQuietSlice(double intervalMs) {
    mIntervalsMs.push_back(intervalMs);
    if (mIntervalsMs.size() > kWindow) mIntervalsMs.pop_front();
}

void FramePacer::recordRenderFrame(double wallMs) {
    mLastRenderFrameMs = wallMs;
    mRenderCompleted = true; // counted with its UI frame (recordUiFrame)
}

double FramePacer::getRenderBudgetMs() const {
    const double ownMs = std::max(0.0, mUiOwnMs);
    return std::max(kMinRenderBudgetMs, kTargetUiFrameMs - ownMs);
}

double FramePacer::getMedianUiFrameMs() const {
    if (mIntervalsMs.empty()) return 0.0;
    std::vector<double> sorted(mIntervalsMs.begin(), mIntervalsMs.end());
    std::sort(sorted.begin(), sorted.end());
    return sorted[sorted.size() / 2];
}

double FramePacer::getMaxUiFrameMs() const {
    if (mIntervalsMs.empty()) return 0.0;
    return *std::max_element(mIntervalsMs.begin(), mIntervalsMs.end());
}

} // namespace ispm
