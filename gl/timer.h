// Per-pass timing. On GPUs, TIME_ELAPSED queries; on llvmpipe they read near zero, so there the
// CPU clock is taken around glFinish() (which serialises the frame: fine for measuring).
#pragma once

#include "gl/objects.h"

#include <chrono>
#include <string>
#include <vector>

namespace gl {

enum class TimingMethod { TimerQuery, CpuFinish };

const char* getTimingMethodName(TimingMethod method);

class PassTimer {
public:
    explicit PassTimer(TimingMethod method) : mMethod(method) {}
    TimingMethod getMethod() const { return mMethod; }

    void begin(const std::string& name);
    void end();
    // Milliseconds of each pass timed since the last call, in order (waits for query results).
    struct Sample {
        std::string name;
        double ms = 0.0;
    };
    std::vector<Sample> collect();

private:
    struct Pending {
        std::string name;
        Query query;
        std::chrono::steady_clock::time_point start;
        double ms = 0.0;
    };
    TimingMethod mMethod;
    std::vector<Pending> mPending;
    std::vector<Query> mFreeQueries;
};

} // namespace gl
