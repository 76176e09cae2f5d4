// Shared CLI helpers.
#include "cli/cli_common.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/debug.h"
#include "render/frame_constants.h"
#include "render/splat_pass.h"
#include "scene/emitters.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

namespace ispm {

void addCameraOption(CLI::App& cmd, std::string& cameraName) {
    cmd.add_option("--camera", cameraName,
                   "view the scene through one of its named `cameras` (docs/scene-format.md)");
}

OutputKind classifyOutput(const std::string& path, const std::string& where) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") return OutputKind::Png;
    if (ext == ".pfm") return OutputKind::Pfm;
    if (ext == ".exr") return OutputKind::Exr;
    throw InputError(
        strCat(where, ": expected a file ending in .png, .pfm or .exr, got '", path, "'"));
}

void checkWritableOutput(const std::string& path, const std::string& where) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code error;
    const auto fail = [&](std::string_view why) {
        return InputError(strCat(where, ": cannot write '", path, "': ", why));
    };
    if (!fs::is_directory(folder, error)) throw fail(strCat("no folder '", folder.string(), "'"));
    if (fs::is_directory(target, error)) throw fail("a folder is in its place");
    // The file is written beside itself and renamed into place (image_io.cpp), or in place.
    const bool folderWritable = access(folder.c_str(), W_OK) == 0;
    const bool fileWritable = fs::exists(target, error) && access(target.c_str(), W_OK) == 0;
    if (!folderWritable && !fileWritable) {
        throw fail(strCat("the folder '", folder.string(), "' is not writable"));
    }
}

Settings makeCommandLineSettings(const std::vector<std::string>& sets, std::optional<int> width,
                                 std::optional<int> height) {
    Settings settings;
    for (const std::string& s : sets)
        settings.setFromString(s, "--set " + s);
    if (width) settings.set("width", *width, "--width");
    if (height) settings.set("height", *height, "--height");
    return settings;
}

void warnIfLightFades(const FrameRunner& runner) {
    const GpuScene& scene = runner.getPasses().scene;
    const std::string warning =
        describeOversizedSplats(scene.getSurfaceArea(), glm::length(scene.getBounds().getExtent()),
                                runner.getFrameSettings());
    if (!warning.empty()) std::fprintf(stderr, "ispm: warning: %s\n", warning.c_str());
    const std::string near = describeRaisedNearPlane(runner.getPasses().model.camera,
                                                     scene.getBounds(), scene.getInstanceBounds());
    if (!near.empty()) std::fprintf(stderr, "ispm: warning: %s\n", near.c_str());
    const std::string dropped = describeDroppedEmitters(runner.getPasses().model);
    if (!dropped.empty()) std::fprintf(stderr, "ispm: warning: %s\n", dropped.c_str());
}

void printTimings(const FrameRunner& runner, const gl::ContextInfo& info) {
    std::printf("renderer: %s (%s); pass times by %s\n", info.renderer.c_str(),
                gl::getContextPathName(info.path),
                gl::getTimingMethodName(runner.getTimings().method));
    double total = 0.0;
    for (const PassTiming& t : runner.getTimings().passes) {
        std::printf("  %-12s %9.2f ms\n", t.name.c_str(), t.ms);
        total += t.ms;
    }
    std::printf("  %-12s %9.2f ms\n", "frame", total);
    const PhotonCounts c = readPhotonCounts(runner);
    if (c.emitted > 0) {
        std::printf("photons: %u emitted, %u after the first bounce, %u stored (%u in view), %u "
                    "overflow\n",
                    c.emitted, c.bounced, c.stored, c.inView, c.overflow);
        const Scene& model = runner.getPasses().model;
        const Emitters& emitters = runner.getPasses().scene.getEmitters();
        for (size_t i = 0; i < c.perLight.size(); ++i) {
            const LightCounts& l = c.perLight[i];
            // The lights, the emitter groups, the environment (GpuScene::getPhotonSourceCount).
            const size_t group = i - model.lights.size();
            std::string name = "environment";
            if (i < model.lights.size()) {
                name = strCat("light ", i, " (", getLightTypeName(model.lights[i].type), ")");
            } else if (group < emitters.groups.size()) {
                name =
                    strCat("emitter '", model.materials[emitters.groups[group].material].name, "'");
            }
            std::printf("  %s: %u emitted, %u after the first bounce, %u stored (%u in view)\n",
                        name.c_str(), l.emitted, l.bounced, l.stored, l.inView);
        }
    }
}

int checkGlErrors(const char* whileDoing) {
    const gl::DebugCounts debug = gl::getDebugCounts();
    if (debug.errors == 0) return 0;
    std::fprintf(stderr, "ispm: %llu OpenGL errors were reported while %s\n",
                 static_cast<unsigned long long>(debug.errors), whileDoing);
    return 1;
}

} // namespace ispm
