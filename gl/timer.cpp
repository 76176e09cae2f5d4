// PassTimer: queries are recycled across frames so timing costs no allocations after warm-up.
#include "gl/timer.h"

#include "gl/context.h"
#include "gl/gl.h"

#include <cassert>

namespace gl {

const char* getTimingMethodName(TimingMethod method) {
    return method == TimingMethod::TimerQuery ? "GPU timer queries"
                                              : "CPU clock around glFinish (software renderer)";
}

TimingMethod chooseTimingMethod(const ContextInfo& info) {
    return info.isSoftware ? TimingMethod::CpuFinish : TimingMethod::TimerQuery;
}

void PassTimer::begin(const std::string& name) {
    Pending pending;
    pending.name = name;
    if (mMethod == TimingMethod::TimerQuery) {
        if (mFreeQueries.empty()) {
            pending.query = Query("pass timer", QueryTarget::TimeElapsed);
        } else {
            pending.query = std::move(mFreeQueries.back());
            mFreeQueries.pop_back();
        }
        pending.query.begin();
    } else {
        glFinish();
        pending.start = std::chrono::steady_clock::now();
    }
    mCurrent.push_back(std::move(pending));
}

void PassTimer::end() {
    assert(!mCurrent.empty());
    Pending& pending = mCurrent.back();
    if (mMethod == TimingMethod::TimerQuery) {
        pending.query.end();
    } else {
        glFinish();
        const auto elapsed = std::chrono::steady_clock::now() - pending.start;
        pending.ms = std::chrono::duration<double, std::milli>(elapsed).count();
    }
}

void PassTimer::endFrame() {
    if (mCurrent.empty()) return;
    mInFlight.push_back(std::move(mCurrent));
    mCurrent.clear();
    while (mInFlight.size() > kMaxFramesInFlight) {
        recycle(mInFlight.front());
        mInFlight.pop_front();
    }
}

bool PassTimer::isAvailable(const Frame& frame) const {
    if (mMethod == TimingMethod::CpuFinish) return true;
    for (const Pending& pending : frame) {
        if (!pending.query.isResultAvailable()) return false;
    }
    return true;
}

std::vector<PassTimer::Sample> PassTimer::read(Frame& frame) {
    constexpr double kNanosecondsPerMillisecond = 1e6;
    std::vector<Sample> samples;
    for (Pending& pending : frame) {
        double ms = pending.ms;
        if (mMethod == TimingMethod::TimerQuery) {
            ms = static_cast<double>(pending.query.getResult()) / kNanosecondsPerMillisecond;
        }
        samples.push_back({pending.name, ms});
    }
    recycle(frame);
    return samples;
}

void PassTimer::recycle(Frame& frame) {
    for (Pending& pending : frame) {
        if (pending.query.getId() != 0) mFreeQueries.push_back(std::move(pending.query));
    }
    frame.clear();
}

std::optional<std::vector<PassTimer::Sample>> PassTimer::collect() {
    endFrame();
    // The newest finished frame wins; it and everything older leave the queue.
    for (size_t i = mInFlight.size(); i-- > 0;) {
        if (!isAvailable(mInFlight[i])) continue;
        std::vector<Sample> samples = read(mInFlight[i]);
        for (size_t j = 0; j < i; ++j)
            recycle(mInFlight[j]);
        mInFlight.erase(mInFlight.begin(), mInFlight.begin() + static_cast<std::ptrdiff_t>(i) + 1);
        return samples;
    }
    return std::nullopt;
}

std::optional<std::vector<PassTimer::Sample>> PassTimer::collectLatest() {
    endFrame();
    if (mInFlight.empty()) return std::nullopt;
    std::vector<Sample> samples = read(mInFlight.back()); // getResult waits
    for (Frame& frame : mInFlight)
        recycle(frame);
    mInFlight.clear();
    return samples;
}

} // namespace gl
