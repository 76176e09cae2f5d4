// frame_ms_target: the photon budget adapted to a frame time. The passes whose work follows the
// photon count (emit, trace, density, splat) are timed apart from the rest, and the budget is
// scaled so that their share fits what the target leaves, in bounded steps with a dead band so
// that it settles instead of oscillating.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ispm {

// One pass's time in a frame (a pass drawn in slices: their sum).
struct PassTiming {
    std::string name;
    double ms = 0.0;
};

// One frame's milliseconds, split into what the photon budget drives and the rest.
struct FrameCost {
    double fixedMs = 0.0;
    double photonMs = 0.0;
};

// Splits a frame's pass times: passes named in `photonPasses` count as photon work.
FrameCost splitFrameCost(const std::vector<PassTiming>& timings,
                         const std::vector<std::string>& photonPasses);

// The budget for the next frames: `photons` times (target - fixed) / photon time, so that the
// photon work fills what the target leaves (its time taken as proportional to the budget); a
// change under 10% is left alone, a step is at most 2x either way, and the result is rounded to
// hundreds and held within [kMinAdaptedPhotons, maxPhotons].
int adaptPhotonBudget(int photons, const FrameCost& cost, double targetMs, int maxPhotons);

inline constexpr int kMinAdaptedPhotons = 1000;

// The photon budget of a running frame_ms_target: the photons of the next frame, and the frames
// measured at them. The frame runner hands it each frame's pass times and applies its photons to
// the frame's settings as a typed override (applyPhotonBudget), never through the settings table.
class FrameBudget {
  public:
    // `maxPhotons`: the top of the setting's range.
    explicit FrameBudget(int maxPhotons) : mMaxPhotons(maxPhotons) {}

    // Starts anew at `photons` (the settings' count), with nothing measured.
    void restart(int photons);
    // Drops the frames measured so far (they ran at other settings); the budget stays.
    void dropMeasurements() { mCosts.clear(); }
    int getPhotons() const { return mPhotons; }

    // The newest measured frame's cost (splitFrameCost). Once kMeasuredFrames frames measured the
    // present budget, moves it towards `targetMs` (their median frame) and returns whether it
    // changed. `converging` (a still view that accumulates) drops the measurements instead: a new
    // budget would disturb it, and once its history is full frames cost nothing. The next
    // `framesInFlight` frames (timer queries answer late) still measure the old budget.
    bool recordFrame(const FrameCost& cost, double targetMs, bool converging,
                     uint32_t framesInFlight);

    // Frames measured at one budget before it changes (their median).
    static constexpr size_t kMeasuredFrames = 3;

  private:
    int mMaxPhotons = 0;
    int mPhotons = 0;
    std::vector<FrameCost> mCosts; // frames measured at the present budget
    uint32_t mSettle = 0;          // frames whose timings may predate the last change
};

} // namespace ispm
