// PassTimer with timer queries reads results without stalling: collect() hands back the newest
// frame whose queries are all done (none while the GPU is still on them), keeps at most
// kMaxFramesInFlight frames waiting, and collectLatest() waits for the last frame's. The CPU
// clock method knows each frame's times at its end.
#include "support/gl_fixture.h"

#include "gl/gl.h"
#include "gl/timer.h"

#include <string>
#include <vector>

namespace ispm::test {
namespace {

class PassTimerTest : public GlTest {};

// One "frame" of two timed passes, each a clear of a small buffer (work the GPU has to do).
void timeFrame(gl::PassTimer& timer, const gl::Buffer& buffer, int frame) {
    for (const char* pass : {"first", "second"}) {
        timer.begin(std::string(pass) + " " + std::to_string(frame));
        buffer.clearToZero();
        timer.end();
    }
}

std::vector<std::string> getNames(const std::vector<gl::PassTimer::Sample>& samples) {
    std::vector<std::string> names;
    for (const gl::PassTimer::Sample& s : samples)
        names.push_back(s.name);
    return names;
}

TEST_F(PassTimerTest, QueriesAreReadFromFinishedFramesWithoutWaiting) {
    gl::PassTimer timer(gl::TimingMethod::TimerQuery);
    const gl::Buffer buffer("timed buffer", 1 << 16);
    timeFrame(timer, buffer, 0);
    timer.endFrame();
    glFinish(); // frame 0 is done on the GPU
    timeFrame(timer, buffer, 1);
    // Frame 1 may or may not be done; frame 0 is, so some finished frame comes back, whole.
    const auto first = timer.collect();
    ASSERT_TRUE(first.has_value());
    const std::vector<std::string> names = getNames(*first);
    const bool frame0 = names == std::vector<std::string>{"first 0", "second 0"};
    const bool frame1 = names == std::vector<std::string>{"first 1", "second 1"};
    EXPECT_TRUE(frame0 || frame1) << names.size();
    for (const gl::PassTimer::Sample& s : *first)
        EXPECT_GE(s.ms, 0.0) << s.name;
    // Frames pile up while none is read, to a bound.
    for (int frame = 2; frame < 12; ++frame) {
        timeFrame(timer, buffer, frame);
        timer.endFrame();
    }
    EXPECT_LE(timer.getFramesInFlight(), gl::PassTimer::kMaxFramesInFlight);
    // Waiting returns the last frame, and nothing stays in flight.
    timeFrame(timer, buffer, 12);
    const auto latest = timer.collectLatest();
    ASSERT_TRUE(latest.has_value());
    EXPECT_EQ(getNames(*latest), (std::vector<std::string>{"first 12", "second 12"}));
    EXPECT_EQ(timer.getFramesInFlight(), 0u);
    EXPECT_FALSE(timer.collect().has_value()) << "no frame was timed since";
}

TEST_F(PassTimerTest, CpuClockKnowsEachFrameAtItsEnd) {
    gl::PassTimer timer(gl::TimingMethod::CpuFinish);
    const gl::Buffer buffer("timed buffer", 1 << 16);
    for (int frame = 0; frame < 3; ++frame) {
        timeFrame(timer, buffer, frame);
        const auto samples = timer.collect();
        ASSERT_TRUE(samples.has_value());
        EXPECT_EQ(getNames(*samples),
                  (std::vector<std::string>{"first " + std::to_string(frame),
                                            "second " + std::to_string(frame)}));
    }
}

} // namespace
} // namespace ispm::test
