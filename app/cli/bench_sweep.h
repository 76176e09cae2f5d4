// `ispm bench --sweep`: speed against accuracy. Renders the cartesian product of setting sweeps,
// measures each configuration's frame time and error against a reference image, times the path
// tracer's own error curve in the same run, writes both to one CSV and prints the equal-error
// speedup.
#pragma once

#include "cli/bench_options.h"
#include "cli/bench_stats.h"
#include "render/frame.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace ispm {

// True when the options ask for a sweep (--sweep, --reference or --csv): runBench hands over.
bool isSweepRequested(const BenchOptions& options);

// `settings` are the effective settings before the sweep (scene, preset, command line). Checks
// every input (sweep values, reference files and sizes, the CSV path) before any GL work and
// throws InputError on bad input.
int runBenchSweep(const BenchOptions& options, const std::string& scenePath, const Scene& scene,
                  const Settings& settings);

// A point of the path tracer's curve: cumulative time and error after some samples per pixel.
struct CurvePoint {
    double timeMs = 0.0;
    double relMse = 0.0;
};

// How long the path tracer needs to reach `relMse`, interpolated log-log between the two curve
// points around its first crossing. Outside the curve the answer is a bound: `Beyond` (the error
// is below the curve's best: the path tracer needs more than `timeMs`) or `BeforeStart` (the error
// is above the first point: it needs at most `timeMs`).
struct EqualErrorTime {
    enum class Kind { Interpolated, Beyond, BeforeStart };
    Kind kind = Kind::Interpolated;
    double timeMs = 0.0;
};
EqualErrorTime findEqualErrorTime(const std::vector<CurvePoint>& curve, double relMse);

} // namespace ispm
