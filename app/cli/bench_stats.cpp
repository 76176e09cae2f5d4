// Bench statistics: times per pass and frame, medians, peak memory.
#include "cli/bench_stats.h"

#include <algorithm>
#include <cassert>
#include <fstream>
#include <sstream>

namespace ispm {
namespace {

constexpr double kKibPerMib = 1024.0;

} // namespace

void addFrameTimes(const FrameRunner& runner, FrameTimes& times) {
    double frameMs = 0.0;
    for (const PassTiming& t : runner.getTimings().passes) {
        auto [it, inserted] = times.samplesMs.try_emplace(t.name);
        if (inserted) times.passOrder.push_back(t.name);
        it->second.push_back(t.ms);
        frameMs += t.ms;
    }
    times.totalsMs.push_back(frameMs);
}

double computeMedian(std::vector<double> samples) {
    assert(!samples.empty());
    std::sort(samples.begin(), samples.end());
    const size_t n = samples.size();
    return n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}

PassStats computeStats(std::string name, const std::vector<double>& samplesMs) {
    const auto [minIt, maxIt] = std::minmax_element(samplesMs.begin(), samplesMs.end());
    return {std::move(name), computeMedian(samplesMs), *minIt, *maxIt};
}

std::optional<double> readPeakRssMib() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) != 0) continue;
        std::istringstream fields(line.substr(line.find(':') + 1));
        double kib = 0.0;
        if (fields >> kib) return kib / kKibPerMib;
    }
    return std::nullopt;
}

} // namespace ispm
