// `ispm render`: one frame of a scene, or a sequence of its animation, headless, to PNG (tone
// mapped) or PFM/EXR (linear).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ispm {

struct RenderOptions {
    std::string scenePath;
    std::string cameraName; // --camera: one of the file's `cameras` ("" = `camera`)
    std::string outputPath;
    std::optional<int> width; // unset: from the settings
    std::optional<int> height;
    std::vector<std::string> sets;
    std::string aov = "total";
    bool quiet = false;
    std::string mode = "ispm";
    int spp = 64;                  // reference mode: samples per pixel
    std::optional<int> bounces;    // setting `bounces`
    std::optional<int> accumulate; // setting `accumulate`: that many frames are rendered
    double timeS = 0.0;            // animation time (seconds); scenes without animation ignore it
    int frames = 1;                // > 1: a sequence, output path with a frame-number pattern
    double fps = 30.0;             // the sequence's frames per second of animation time
};

// A sequence's output path for frame `index`: the pattern's one printf integer conversion (%d,
// %4d or %04d) replaced by the number, %% by %. Throws InputError (naming `where`) when the
// pattern has no such conversion, several, or another % sequence.
std::string formatFramePath(const std::string& pattern, int index, const std::string& where);

void addRenderCommand(CLI::App& app, RenderOptions& options);
int runRender(const RenderOptions& options);

} // namespace ispm
