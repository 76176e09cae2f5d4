// frame_ms_target: the photon budget adapted to a frame time. The passes whose work follows the
// photon count (emit, trace, density, splat) are timed apart from the rest, and the budget is
// scaled so that their share fits what the target leaves, in bounded steps with a dead band so
// that it settles instead of oscillating.
#pragma once

#include <string>
#include <vector>

namespace ispm {

struct PassTiming;

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

} // namespace ispm
