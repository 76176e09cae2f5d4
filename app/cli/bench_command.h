// `ispm bench`: time every pass over many frames after a warm-up and report medians, peak memory
// and the settings used, as a table or as one JSON object for scripts and plots. With --sweep it
// measures speed against accuracy instead (bench_sweep.h).
#pragma once

#include "cli/bench_options.h"

namespace CLI {
class App;
}

namespace ispm {

void addBenchCommand(CLI::App& app, BenchOptions& options);
int runBench(const BenchOptions& options);

} // namespace ispm
