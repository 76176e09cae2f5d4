// `ispm render`: one frame of a scene, headless, to PNG (tone mapped) or PFM/EXR (linear).
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
};

void addRenderCommand(CLI::App& app, RenderOptions& options);
int runRender(const RenderOptions& options);

} // namespace ispm
