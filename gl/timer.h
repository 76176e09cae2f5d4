// Per-pass timing. On GPUs, TIME_ELAPSED queries, read without stalling the frame: each frame's
// queries stay in flight until their results are available, and collect() returns the newest
// frame whose results are all in (a frame or a few late), as profilers in real-time engines do;
// only collectLatest() waits (bench, and render's one frame). On llvmpipe the queries read near
// zero, so there the CPU clock is taken around glFinish() (which serialises the frame: fine for
// measuring), and every frame's times are known at its end.
#pragma once

#include "gl/objects.h"

#include <chrono>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace gl {

struct ContextInfo;

enum class TimingMethod { TimerQuery, CpuFinish };

const char* getTimingMethodName(TimingMethod method);
// The method that gives true pass times on this context: the CPU clock around glFinish on a
// software renderer, whose timer queries read near zero; timer queries on a GPU, where they do
// not stall the frame.
TimingMethod chooseTimingMethod(const ContextInfo& info);

class PassTimer {
  public:
    // Frames whose queries may wait for their results; an older one is dropped unread.
    static constexpr size_t kMaxFramesInFlight = 4;

    explicit PassTimer(TimingMethod method) : mMethod(method) {}
    TimingMethod getMethod() const { return mMethod; }

    void begin(const std::string& name);
    void end();
    struct Sample {
        std::string name;
        double ms = 0.0;
    };
    // Ends the frame whose passes were timed since the last call. Returns the times of the newest
    // frame whose results are all available (this one with CpuFinish), without waiting; nothing
    // when no frame has finished since the last result. Older frames in flight are dropped.
    std::optional<std::vector<Sample>> collect();
    // Waits for every frame in flight and returns the newest one's times (nothing when no frame
    // was timed since the last result).
    std::optional<std::vector<Sample>> collectLatest();
    // Ends the frame without reading any results (collect() does both).
    void endFrame();
    // Forgets the passes timed since the last endFrame (a frame dropped half way).
    void discardFrame() { recycle(mCurrent); }
    size_t getFramesInFlight() const { return mInFlight.size(); }

  private:
    struct Pending {
        std::string name;
        Query query;
        std::chrono::steady_clock::time_point start;
        double ms = 0.0;
    };
    using Frame = std::vector<Pending>;

    bool isAvailable(const Frame& frame) const;
    // The frame's times; its queries go back to the free list.
    std::vector<Sample> read(Frame& frame);
    void recycle(Frame& frame);

    TimingMethod mMethod;
    Frame mCurrent;
    std::deque<Frame> mInFlight; // oldest first
    std::vector<Query> mFreeQueries;
};

} // namespace gl
