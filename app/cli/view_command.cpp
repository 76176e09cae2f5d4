// View command: every input (scene, settings, script, screenshot path) is checked before the
// window opens, so bad input exits 2 without a display.
#include "cli/view_command.h"

#include "cli/cli_common.h"
#include "core/input_error.h"
#include "core/strings.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"
#include "viewer/viewer.h"

#include <CLI/CLI.hpp>

#include <filesystem>

namespace ispm {

void addViewCommand(CLI::App& app, ViewOptions& options) {
    CLI::App* cmd = app.add_subcommand("view", "Open the interactive viewer on a window");
    cmd->add_option("scene", options.scenePath, "scene file (JSON)")->required();
    addCameraOption(*cmd, options.cameraName);
    cmd->add_option("--width", options.width, "render width in pixels (the panel is added)");
    cmd->add_option("--height", options.height, "render height in pixels");
    cmd->add_option("--set", options.sets, "override a setting: name=value (repeatable)");
    cmd->add_option("--frames", options.frames,
                    "exit after N finished frames (default: when closed)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--screenshot", options.screenshotPath,
                    "with --frames: write the last frame's window (UI included) as PNG");
    cmd->add_option(
        "--script", options.scriptPath,
        "replay input from a file (key, mouse_drag, click, type, set, view, frames ...)");
    cmd->add_option("--reference", options.referencePath,
                    "reference image (.pfm or .exr) for the side-by-side and error views");
    cmd->footer(
        "Keys: WASD/QE fly, left drag looks, wheel sets the speed, F1 lists the keys, F2 hides the "
        "frame-rate overlay, F5 reloads changed shaders, F12 writes a screenshot, Ctrl+Q quits.");
}

int runView(const ViewOptions& options) {
    if (!options.screenshotPath.empty()) {
        if (getImageFormatFromPath(options.screenshotPath) != ImageFormat::Png) {
            throw InputError(
                strCat("--screenshot: expected a .png file, got '", options.screenshotPath, "'"));
        }
        if (options.frames < 1) {
            throw InputError("--screenshot: needs --frames N, N >= 1 (it writes the last frame)");
        }
    }
    ViewerOptions viewer;
    viewer.maxFrames = options.frames;
    viewer.screenshotPath = options.screenshotPath;
    if (!options.referencePath.empty()) {
        const ImageFormat format = getImageFormatFromPath(options.referencePath);
        if (format != ImageFormat::Pfm && format != ImageFormat::Exr) {
            throw InputError(strCat("--reference: expected a .pfm or .exr file, got '",
                                    options.referencePath, "'"));
        }
        if (!std::filesystem::is_regular_file(options.referencePath)) {
            throw InputError(strCat("--reference: no such file '", options.referencePath, "'"));
        }
        viewer.referencePath = options.referencePath;
    }
    if (!options.scriptPath.empty()) viewer.script = loadInputScript(options.scriptPath);
    const Settings commandLine =
        makeCommandLineSettings(options.sets, options.width, options.height);
    Scene scene = loadScene(options.scenePath);
    selectCamera(scene, options.cameraName);
    scene.settings.merge(commandLine);
    viewer.commandLine = commandLine;
    return runViewer(std::move(scene), viewer);
}

} // namespace ispm
