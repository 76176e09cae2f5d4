// Render command: load, check every input before any GL work, render, read back, write.
#include "cli/render_command.h"

#include "cli/cli_common.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "image/image_io.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/input_error.h"
#include "scene/scene_loader.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>

namespace ispm {

void addRenderCommand(CLI::App& app, RenderOptions& options) {
    CLI::App* cmd = app.add_subcommand("render", "Render one frame of a scene headless");
    cmd->add_option("scene", options.scenePath, "scene file (JSON)")->required();
    cmd->add_option("-o,--output", options.outputPath,
                    "output image: .png (tone mapped) or .pfm/.exr (linear radiance)")
        ->required();
    cmd->add_option("--width", options.width, "image width in pixels (setting `width`)");
    cmd->add_option("--height", options.height, "image height in pixels (setting `height`)");
    cmd->add_option("--set", options.sets, "override a setting: name=value (repeatable)");
    cmd->add_option("--aov", options.aov,
                    "linear output for .pfm/.exr: direct, indirect or total (default total)");
    cmd->add_flag("-q,--quiet", options.quiet, "print only errors");
    cmd->footer("Renders a warm-up frame first and prints the per-pass times of the second.");
}

int runRender(const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const OutputKind kind = classifyOutput(options.outputPath, "--output");
    const Aov aov = parseAov(options.aov, "--aov");
    if (kind == OutputKind::Png && aov != Aov::Total) {
        throw InputError(strCat("--aov: a PNG holds the tone-mapped total; write .pfm or .exr for '",
                                options.aov, "'"));
    }
    const Settings commandLine = makeCommandLineSettings(options.sets, options.width, options.height);
    const Scene scene = loadScene(options.scenePath);
    Settings settings = scene.settings;
    settings.merge(commandLine);

    auto context = gl::createHeadlessContext();
    const gl::TimingMethod timing = context->getInfo().isSoftware ? gl::TimingMethod::CpuFinish
                                                                  : gl::TimingMethod::TimerQuery;
    FrameRunner runner(scene, settings, timing);
    // The first frame compiles shaders in the driver and touches every resource once; time the
    // second, which is what every later frame costs.
    runner.renderFrame();
    runner.renderFrame();
    const Image image = readTextureImage(runner.getAov(kind == OutputKind::Png ? Aov::Display : aov));
    writeImage(options.outputPath, image);
    const gl::DebugCounts debug = gl::getDebugCounts();
    if (!options.quiet) {
        const double totalMs = std::chrono::duration<double, std::milli>(
                                   std::chrono::steady_clock::now() - start)
                                   .count();
        std::printf("wrote %s (%dx%d, %s)\n", options.outputPath.c_str(), runner.getWidth(),
                    runner.getHeight(), kind == OutputKind::Png ? "tone mapped" : options.aov.c_str());
        printTimings(runner, context->getInfo());
        std::printf("whole command: %.1f ms (scene load, context, shader builds, frame, write)\n",
                    totalMs);
    }
    if (debug.errors > 0) {
        std::fprintf(stderr, "ispm: %llu OpenGL errors were reported while rendering\n",
                     static_cast<unsigned long long>(debug.errors));
        return 1;
    }
    return 0;
}

} // namespace ispm
