// Render command: load, check every input before any GL work, render, read back, write.
#include "cli/render_command.h"

#include "cli/cli_common.h"
#include "core/input_error.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "image/image_io.h"
#include "render/frame.h"
#include "render/readback.h"
#include "render/reference_pass.h"
#include "scene/frame_settings.h"
#include "scene/scene_loader.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace ispm {
namespace {

// One frame of motion for motion blur: a 60 Hz display's, the step bench --animate uses.
constexpr double kMotionFrameSeconds = 1.0 / 60.0;

} // namespace

void addRenderCommand(CLI::App& app, RenderOptions& options) {
    CLI::App* cmd = app.add_subcommand("render", "Render one frame of a scene headless");
    cmd->add_option("scene", options.scenePath, "scene file (JSON)")->required();
    cmd->add_option("-o,--output", options.outputPath,
                    "output image: .png (tone mapped) or .pfm/.exr (linear radiance)")
        ->required();
    addCameraOption(*cmd, options.cameraName);
    cmd->add_option("--width", options.width, "image width in pixels (setting `width`)");
    cmd->add_option("--height", options.height, "image height in pixels (setting `height`)");
    cmd->add_option("--set", options.sets, "override a setting: name=value (repeatable)");
    cmd->add_option("--aov", options.aov,
                    "linear output for .pfm/.exr: direct, indirect or total (default total)");
    cmd->add_flag("-q,--quiet", options.quiet, "print only errors");
    cmd->add_option("--mode", options.mode,
                    "ispm (image-space photon mapping, default) or reference (path tracer)");
    cmd->add_option("--spp", options.spp, "reference mode: samples per pixel (default 64)");
    cmd->add_option("--bounces", options.bounces,
                    "reflections between light and visible surface (setting `bounces`; 0 = direct "
                    "light; reference default 64)");
    cmd->add_option("--accumulate", options.accumulate,
                    "render this many frames of the still scene, each with new photons, and write "
                    "their average (setting `accumulate`; 0 = one frame)");
    cmd->add_option("--time", options.timeS,
                    "animation time in seconds, >= 0 (default 0): where animated objects and "
                    "lights are (docs/scene-format.md, Animation)");
    cmd->footer("ispm mode renders a warm-up frame first and prints the per-pass times of the "
                "second. reference mode accumulates --spp jittered samples per pixel with a "
                "progress bar on a terminal and writes linear .pfm/.exr only.");
}

namespace {

bool isTerminal() {
    return ::isatty(::fileno(stderr)) != 0;
}

void printProgress(int done, int total, double elapsedS) {
    constexpr int kBarWidth = 30;
    const int filled = total > 0 ? done * kBarWidth / total : kBarWidth;
    const double left = done > 0 ? elapsedS / done * (total - done) : 0.0;
    std::fprintf(stderr, "\r[%s%s] %d/%d spp, %.1f s left  ",
                 std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(kBarWidth - filled), '.').c_str(), done, total, left);
    if (done == total) std::fprintf(stderr, "\n");
}

int runReference(const RenderOptions& options, const Scene& scene, const Settings& settings,
                 std::chrono::steady_clock::time_point start) {
    auto context = gl::createHeadlessContext();
    ReferencePass reference(scene, settings);
    const bool progress = !options.quiet && isTerminal();
    const auto traceStart = std::chrono::steady_clock::now();
    auto secondsSince = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    for (int s = 0; s < options.spp; ++s) {
        reference.addSample();
        if (progress) printProgress(s + 1, options.spp, secondsSince(traceStart));
    }
    writeImage(options.outputPath, reference.readMean());
    if (!options.quiet) {
        std::printf("wrote %s (%dx%d, reference, %d spp, %d bounces)\n", options.outputPath.c_str(),
                    resolveFrameSettings(settings).width, resolveFrameSettings(settings).height,
                    options.spp, reference.getBounces());
        std::printf("path tracing: %.1f ms; whole command: %.1f ms\n",
                    secondsSince(traceStart) * 1e3, secondsSince(start) * 1e3);
    }
    return checkGlErrors("path tracing");
}

} // namespace

int runRender(const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const OutputKind kind = classifyOutput(options.outputPath, "--output");
    checkWritableOutput(options.outputPath, "--output");
    const Aov aov = parseAov(options.aov, "--aov");
    if (options.mode != "ispm" && options.mode != "reference") {
        throw InputError(strCat("--mode: expected ispm or reference, got '", options.mode, "'"));
    }
    const bool isReference = options.mode == "reference";
    if (kind == OutputKind::Png && aov != Aov::Total) {
        throw InputError(
            strCat("--aov: a PNG holds the tone-mapped total; write .pfm or .exr for '",
                   options.aov, "'"));
    }
    if (isReference && kind == OutputKind::Png) {
        throw InputError("--output: reference mode writes linear radiance: expected .pfm or .exr");
    }
    if (isReference && aov != Aov::Total) {
        throw InputError("--aov: reference mode writes the total; --bounces 0 gives direct light");
    }
    if (options.spp < 1) throw InputError(strCat("--spp: expected at least 1, got ", options.spp));
    if (!std::isfinite(options.timeS) || options.timeS < 0.0) {
        throw InputError(strCat("--time: expected a number of seconds >= 0, got ", options.timeS));
    }
    Settings commandLine = makeCommandLineSettings(options.sets, options.width, options.height);
    if (options.bounces) commandLine.set("bounces", *options.bounces, "--bounces");
    if (options.accumulate) commandLine.set("accumulate", *options.accumulate, "--accumulate");
    Scene scene = loadScene(options.scenePath);
    selectCamera(scene, options.cameraName);
    if (scene.isAnimated()) scene.update(options.timeS);
    Settings settings = scene.settings;
    settings.merge(commandLine);
    if (isReference) return runReference(options, scene, settings, start);

    auto context = gl::createHeadlessContext();
    const gl::TimingMethod timing =
        context->getInfo().isSoftware ? gl::TimingMethod::CpuFinish : gl::TimingMethod::TimerQuery;
    FrameRunner runner(scene, settings, timing);
    warnIfLightFades(runner);
    // The first frame compiles shaders in the driver and touches every resource once; time the
    // second, which is what every later frame costs. Accumulating, every frame counts: the image
    // is the average of `accumulate` frames.
    const int accumulate = runner.getFrameSettings().accumulate;
    const int frames = accumulate > 0 ? accumulate : 2;
    // Motion blur follows the motion since the last frame: the warm-up frame shows the scene one
    // 60 Hz frame earlier (at 0 when --time is under a frame), so the image at --time has a
    // last frame to move from.
    const bool blurMotion = runner.getFrameSettings().hasMotionBlur() && scene.isAnimated();
    if (blurMotion && accumulate == 0) {
        scene.update(std::max(0.0, options.timeS - kMotionFrameSeconds));
        runner.updateScene();
    }
    for (int i = 0; i < frames; ++i) {
        if (blurMotion && accumulate == 0 && i == 1) {
            scene.update(options.timeS);
            runner.updateScene();
        }
        runner.renderFrame();
    }
    runner.waitForTimings(); // one frame to report: the frame is over, waiting costs nothing
    const Image image =
        readTextureImage(runner.getAov(kind == OutputKind::Png ? Aov::Display : aov));
    writeImage(options.outputPath, image);
    if (!options.quiet) {
        const double totalMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        std::printf("wrote %s (%dx%d, %s)\n", options.outputPath.c_str(), runner.getWidth(),
                    runner.getHeight(),
                    kind == OutputKind::Png ? "tone mapped" : options.aov.c_str());
        if (accumulate > 0) {
            std::printf("indirect light: %u frames accumulated (seeds %u to %u)\n",
                        runner.getAccumulatedFrames(), runner.getFrameSettings().seed,
                        runner.getFrameSettings().seed + uint32_t(frames) - 1);
        }
        printTimings(runner, context->getInfo());
        std::printf("whole command: %.1f ms (scene load, context, shader builds, frame, write)\n",
                    totalMs);
    }
    return checkGlErrors("rendering");
}

} // namespace ispm
