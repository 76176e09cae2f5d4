// PassTimer: queries are recycled across frames so timing costs no allocations after warm-up.
#include "gl/timer.h"

#include "gl/gl.h"

#include <cassert>

namespace gl {

const char* getTimingMethodName(TimingMethod method) {
    return method == TimingMethod::TimerQuery ? "GPU timer queries"
                                              : "CPU clock around glFinish (software renderer)";
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
    mPending.push_back(std::move(pending));
}

void PassTimer::end() {
    assert(!mPending.empty());
    Pending& pending = mPending.back();
    if (mMethod == TimingMethod::TimerQuery) {
        pending.query.end();
    } else {
        glFinish();
        const auto elapsed = std::chrono::steady_clock::now() - pending.start;
        pending.ms = std::chrono::duration<double, std::milli>(elapsed).count();
    }
}

std::vector<PassTimer::Sample> PassTimer::collect() {
    constexpr double kNanosecondsPerMillisecond = 1e6;
    std::vector<Sample> samples;
    for (Pending& pending : mPending) {
        double ms = pending.ms;
        if (mMethod == TimingMethod::TimerQuery) {
            ms = static_cast<double>(pending.query.getResult()) / kNanosecondsPerMillisecond;
            mFreeQueries.push_back(std::move(pending.query));
        }
        samples.push_back({pending.name, ms});
    }
    mPending.clear();
    return samples;
}

} // namespace gl
