// `ispm view`: the interactive viewer on a window (GLFW + Dear ImGui), optionally scripted and
// bounded in frames for tests and screenshots.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ispm {

struct ViewOptions {
    std::string scenePath;
    std::string cameraName;   // --camera: one of the file's `cameras` ("" = `camera`)
    std::optional<int> width; // unset: from the settings
    std::optional<int> height;
    std::vector<std::string> sets;
    int frames = -1;
    std::string screenshotPath;
    std::string scriptPath;
    std::string referencePath;
};

void addViewCommand(CLI::App& app, ViewOptions& options);
int runView(const ViewOptions& options);

} // namespace ispm
