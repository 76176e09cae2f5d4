// frame_ms_target's controller (see frame_budget.h).
#include "render/frame_budget.h"

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// Within this relative change the budget stays: pass times move by a few percent from frame to
// frame on their own (and far more on a shared machine), which must not move the budget.
constexpr double kDeadBand = 0.1;
// At most this factor per step: the photon work is not quite proportional to the budget (the
// splat follows covered pixels, the density pass its grid), so the next measurement corrects it.
constexpr double kMaxStep = 2.0;
constexpr int kRounding = 100;

} // namespace

FrameCost splitFrameCost(const std::vector<PassTiming>& timings,
                         const std::vector<std::string>& photonPasses) {
    FrameCost cost;
    for (const PassTiming& t : timings) {
        const bool photonWork =
            std::find(photonPasses.begin(), photonPasses.end(), t.name) != photonPasses.end();
        (photonWork ? cost.photonMs : cost.fixedMs) += t.ms;
    }
    return cost;
}

int adaptPhotonBudget(int photons, const FrameCost& cost, double targetMs, int maxPhotons) {
    if (targetMs <= 0.0 || photons <= 0 || cost.photonMs <= 0.0) return photons;
    const double wanted = std::max(targetMs - cost.fixedMs, 0.0) / cost.photonMs;
    if (std::abs(wanted - 1.0) < kDeadBand) return photons;
    const double step = std::clamp(wanted, 1.0 / kMaxStep, kMaxStep);
    const double next = std::round(double(photons) * step / kRounding) * kRounding;
    return int(
        std::clamp(next, double(std::min(kMinAdaptedPhotons, maxPhotons)), double(maxPhotons)));
}

void FrameBudget::restart(int photons) {
    mPhotons = photons;
    mCosts.clear();
}

bool FrameBudget::recordFrame(const FrameCost& cost, double targetMs, bool converging,
                              uint32_t framesInFlight) {
    if (targetMs <= 0.0 || converging) {
        mCosts.clear();
        return false;
    }
    if (mSettle > 0) {
        --mSettle;
        return false;
    }
    mCosts.push_back(cost);
    if (mCosts.size() < kMeasuredFrames) return false;
    // The median frame of the window: one slow frame (another process, a first use of a
    // program) does not move the budget.
    std::sort(mCosts.begin(), mCosts.end(), [](const FrameCost& a, const FrameCost& b) {
        return a.fixedMs + a.photonMs < b.fixedMs + b.photonMs;
    });
    const FrameCost median = mCosts[mCosts.size() / 2];
    mCosts.clear();
    const int photons = adaptPhotonBudget(mPhotons, median, targetMs, mMaxPhotons);
    if (photons == mPhotons) return false;
    mPhotons = photons;
    // Timer queries answer frames late: the frames still in flight measure the old budget.
    mSettle = framesInFlight;
    return true;
}

} // namespace ispm
