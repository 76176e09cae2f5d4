// The options of `ispm bench`, shared by its two modes: the plain bench (bench_command.h) parses
// them and hands a sweep over to bench_sweep.h, which needs the options, not the command.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ispm {

struct BenchOptions {
    std::string scenePath;  // optional only with a preset, which then supplies the scene
    std::string cameraName; // --camera: one of the file's `cameras` ("" = `camera`)
    int frames = 10;        // timed frames
    // The first use of a program costs about 60 ms on llvmpipe: frames before the timed ones
    // absorb that (docs/design.md "The test renderer (llvmpipe)").
    int warmup = 2;
    std::optional<int> width; // unset: from the preset or the settings
    std::optional<int> height;
    std::vector<std::string> sets;
    bool json = false;
    std::string preset; // "" or "thesis"
    // Every frame (warm-up and timed) advances the animation by 1/60 s and re-uploads the moved
    // scene (top-level BVH, light cameras), timed as the row "scene update".
    bool animate = false;
    // --flicker N: N timed frames whose indirect light is read back and measured for flicker
    // (bench_flicker.h); pixels farther than flickerAwayM from moving objects count apart.
    std::optional<int> flickerFrames;
    double flickerAwayM = 0.5;
    // Sweep mode (bench_sweep.h): any of these turns it on.
    std::vector<std::string> sweeps; // "name=v1,v2,..." each
    std::string referencePath;       // linear .pfm/.exr the configurations are measured against
    std::string referenceDirectPath; // optional bounces=0 reference: isolates indirect light
    std::string csvPath;
    // The path tracer's curve ends here; 64 spp at 256^2 takes seconds on llvmpipe.
    int referenceSppMax = 64;
    // Passes over every configuration: each configuration's frames are timed once per round
    // (their medians over all rounds), so that a slow spell of a shared machine lands on every
    // configuration's frames alike instead of on the few measured during it.
    int rounds = 1;
};

} // namespace ispm
