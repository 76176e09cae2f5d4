// frame_ms_target's controller (render/frame_budget.h) on simulated frame costs: it settles near
// the target without oscillating, leaves small differences alone, steps at most 2x and stays in
// range.
#include "render/frame_budget.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace ispm {
namespace {

constexpr int kMaxPhotons = 16777216;

// Runs the controller against a cost model for `steps` adaptations; returns the budgets.
std::vector<int> simulate(int photons, double targetMs, const std::function<FrameCost(int)>& costOf,
                          int steps) {
    std::vector<int> budgets = {photons};
    for (int i = 0; i < steps; ++i) {
        photons = adaptPhotonBudget(photons, costOf(photons), targetMs, kMaxPhotons);
        budgets.push_back(photons);
    }
    return budgets;
}

TEST(FrameBudget, SplitsPhotonPassesFromTheRest) {
    const std::vector<PassTiming> timings = {
        {"gbuffer", 10.0}, {"emit", 2.0}, {"trace", 5.0}, {"splat", 40.0}, {"tonemap", 3.0}};
    const FrameCost cost = splitFrameCost(timings, {"emit", "trace", "density", "splat"});
    EXPECT_DOUBLE_EQ(cost.photonMs, 47.0);
    EXPECT_DOUBLE_EQ(cost.fixedMs, 13.0);
}

TEST(FrameBudget, SettlesOnALinearCostWithoutOscillating) {
    // 50 ms fixed, 4 us a photon: 150 ms holds 25,000 photons.
    const auto linear = [](int photons) { return FrameCost{50.0, 0.004 * photons}; };
    for (const int start : {200000, 1000, 24000}) {
        const std::vector<int> budgets = simulate(start, 150.0, linear, 12);
        // Within the dead band of 25,000 after a few steps (2x steps from 200,000: 3 halvings).
        const int last = budgets.back();
        EXPECT_NEAR(last, 25000, 2500) << start;
        // Monotone on the way (no overshoot to come back from), and still once there.
        for (size_t i = 1; i < budgets.size(); ++i) {
            const int direction = start > 25000 ? -1 : 1;
            EXPECT_GE(direction * (budgets[i] - budgets[i - 1]), 0) << start << " step " << i;
        }
        EXPECT_EQ(budgets[budgets.size() - 2], last) << start;
    }
}

TEST(FrameBudget, SettlesWhenPhotonWorkGrowsSlowerThanTheBudget) {
    // The splat follows covered pixels more than photons: time ~ photons^0.6.
    const auto sublinear = [](int photons) {
        return FrameCost{30.0, 0.5 * std::pow(double(photons) / 1000.0, 0.6)};
    };
    const std::vector<int> budgets = simulate(20000, 60.0, sublinear, 20);
    // Settled: the last steps change nothing, and the frame is within 10% of the target.
    EXPECT_EQ(budgets[budgets.size() - 1], budgets[budgets.size() - 4]);
    const FrameCost cost = sublinear(budgets.back());
    EXPECT_NEAR(cost.fixedMs + cost.photonMs, 60.0, 0.1 * 60.0 + 1.0);
}

TEST(FrameBudget, DeadBandStepsAndRange) {
    const FrameCost cost{10.0, 100.0};
    EXPECT_EQ(adaptPhotonBudget(50000, cost, 0.0, kMaxPhotons), 50000);     // off
    EXPECT_EQ(adaptPhotonBudget(50000, cost, 115.0, kMaxPhotons), 50000);   // 5% off: left alone
    EXPECT_EQ(adaptPhotonBudget(50000, cost, 1000.0, kMaxPhotons), 100000); // 2x at most
    EXPECT_EQ(adaptPhotonBudget(50000, cost, 5.0, kMaxPhotons), 25000);     // half at most
    EXPECT_EQ(adaptPhotonBudget(1500, cost, 5.0, kMaxPhotons), kMinAdaptedPhotons);
    EXPECT_EQ(adaptPhotonBudget(60000, cost, 1000.0, 100000), 100000);   // the setting's maximum
    EXPECT_EQ(adaptPhotonBudget(50000, cost, 60.0, kMaxPhotons), 25000); // (60 - 10) / 100
}

TEST(FrameBudget, MeasuresThreeFramesThenSteps) {
    // 10 ms fixed and 100 ms of photons against a 60 ms target: (60 - 10) / 100, half the budget.
    const FrameCost frame = splitFrameCost({{"gbuffer", 10.0}, {"splat", 100.0}}, {"splat"});
    FrameBudget budget(kMaxPhotons);
    budget.restart(50000);
    EXPECT_FALSE(budget.recordFrame(frame, 60.0, false, 0));
    EXPECT_FALSE(budget.recordFrame(frame, 60.0, false, 0));
    EXPECT_TRUE(budget.recordFrame(frame, 60.0, false, 0));
    EXPECT_EQ(budget.getPhotons(), 25000);
    // Two frames still in flight measured the old budget: they are skipped, then three more.
    budget.restart(50000);
    for (int f = 0; f < 2; ++f)
        budget.recordFrame(frame, 60.0, false, 0);
    EXPECT_TRUE(budget.recordFrame(frame, 60.0, false, 2));
    for (int f = 0; f < 4; ++f)
        EXPECT_FALSE(budget.recordFrame(frame, 60.0, false, 0)) << f;
    EXPECT_TRUE(budget.recordFrame(frame, 60.0, false, 0));
    EXPECT_EQ(budget.getPhotons(), 12500);
}

TEST(FrameBudget, ConvergingOrOffDropsTheMeasurements) {
    const FrameCost frame = splitFrameCost({{"gbuffer", 10.0}, {"splat", 100.0}}, {"splat"});
    FrameBudget budget(kMaxPhotons);
    budget.restart(50000);
    budget.recordFrame(frame, 60.0, false, 0);
    budget.recordFrame(frame, 60.0, false, 0);
    EXPECT_FALSE(budget.recordFrame(frame, 60.0, true, 0)); // a still view converging
    EXPECT_FALSE(budget.recordFrame(frame, 60.0, false, 0));
    EXPECT_FALSE(budget.recordFrame(frame, 0.0, false, 0)); // off
    EXPECT_EQ(budget.getPhotons(), 50000);
    budget.dropMeasurements();
    budget.recordFrame(frame, 60.0, false, 0);
    budget.recordFrame(frame, 60.0, false, 0);
    EXPECT_TRUE(budget.recordFrame(frame, 60.0, false, 0));
}

} // namespace
} // namespace ispm
