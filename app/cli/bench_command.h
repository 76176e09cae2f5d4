// `ispm bench`: time every pass over many frames after a warm-up and report medians, peak memory
// and the settings used, as a table or as one JSON object for scripts and plots.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ispm {

struct BenchOptions {
    std::string scenePath; // optional only with a preset, which then supplies the scene
    int frames = 10;       // timed frames
    // The first use of a program costs about 60 ms on llvmpipe (DESIGN.md): frames before the
    // timed ones absorb that.
    int warmup = 2;
    std::optional<int> width; // unset: from the preset or the settings
    std::optional<int> height;
    std::vector<std::string> sets;
    bool json = false;
    std::string preset; // "" or "thesis"
};

void addBenchCommand(CLI::App& app, BenchOptions& options);
int runBench(const BenchOptions& options);

} // namespace ispm
