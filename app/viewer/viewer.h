// `ispm view`: the interactive viewer. A GLFW window shows the frame (or a debug view) on the left
// and the ImGui panels on the right: settings from the table, camera, lights, timings, photon
// counts. Scripts replay input through the same paths for tests.
#pragma once

#include "scene/scene.h"
#include "viewer/input_script.h"

#include <string>
#include <vector>

namespace ispm {

struct ViewerOptions {
    int maxFrames = -1;         // < 0: until the window is closed
    std::string screenshotPath; // written from the last frame when maxFrames ends the run
    std::string referencePath;  // .pfm/.exr for the reference views, or empty
    std::vector<ScriptCommand> script;
    bool visible = true;
    // Layered over a scene picked in the viewer's scene picker, as over the first one.
    Settings commandLine;
};

// Runs until the window closes or maxFrames frames were shown. `scene.settings` are the effective
// settings (width and height are the render region; the window adds the panel). The scene picker
// lists the JSON files beside `scene.sourcePath`. Returns the exit code: 0, or 1 when OpenGL
// reported errors.
int runViewer(Scene scene, const ViewerOptions& options);

} // namespace ispm
