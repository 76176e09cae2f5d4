// Statistics both benches share (the plain one and the sweep): per-pass and per-frame times of
// a run of frames, their medians, and the process's peak memory.
#pragma once

#include "render/frame.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ispm {

// Per-pass and per-frame times of a run of frames; passes keep the order of their first
// appearance, so passes added later need no change in the callers.
struct FrameTimes {
    std::vector<std::string> passOrder;
    std::map<std::string, std::vector<double>> samplesMs; // by pass name
    std::vector<double> totalsMs;                         // sum of the passes, per frame
};

// Appends the timings of the runner's last frame.
void addFrameTimes(const FrameRunner& runner, FrameTimes& times);

// Median of `samples` (not empty).
double computeMedian(std::vector<double> samples);

struct PassStats {
    std::string name;
    double medianMs = 0.0;
    double minMs = 0.0;
    double maxMs = 0.0;
};

// Median, minimum and maximum of `samplesMs` (not empty).
PassStats computeStats(std::string name, const std::vector<double>& samplesMs);

// Peak resident set size (VmHWM) in MiB; empty where /proc is not there to ask.
std::optional<double> readPeakRssMib();

} // namespace ispm
