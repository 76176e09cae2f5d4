// Render command: load, check every input before any GL work, render, read back, write.
#include "cli/render_command.h"

#include "cli/cli_common.h"
#include "core/input_error.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/timer.h"
#include "image/image_io.h"
#include "render/frame.h"
#include "render/photon_points.h"
#include "render/readback.h"
#include "render/reference_pass.h"
#include "scene/scene_loader.h"
#include "settings/frame_settings.h"

#include <shared/light_trace_data.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

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
                    "linear output for .pfm/.exr: direct, indirect or total (default total); or a "
                    "photon-buffer image for .png: bounce_direction, bounce_power, "
                    "result_direction or result_power (photons as points over the dimmed frame)");
    cmd->add_flag("-q,--quiet", options.quiet, "print only errors");
    cmd->add_option("--mode", options.mode,
                    "ispm (image-space photon mapping, default) or reference (path tracer; "
                    "--set reference_method=light: light tracer, sees caustics)");
    cmd->add_option("--spp", options.spp, "reference mode: samples per pixel (default 64)");
    cmd->add_option("--bounces", options.bounces,
                    "reflections between light and visible surface (setting `bounces`; 0 = direct "
                    "light; reference default 64)");
    cmd->add_option("--accumulate", options.accumulate,
                    "render this many frames of the still scene, each with new photons, and write "
                    "their average (setting `accumulate`; 0 = one frame)");
    cmd->add_option("--time", options.timeS,
                    "animation time in seconds, >= 0 (default 0): where animated objects, lights "
                    "and the camera are (docs/scene-format.md, Animation); a sequence's start");
    cmd->add_option("--frames", options.frames,
                    "render a sequence of this many frames from --time on, one every 1/--fps s of "
                    "animation time, to -o with a frame number (e.g. out_%04d.png); default 1");
    cmd->add_option("--fps", options.fps,
                    "frames per second of a sequence (default 30): its time step, which eye "
                    "adaptation (setting eye_adaptation_s) follows");
    cmd->footer("ispm mode renders a warm-up frame first and prints the per-pass times of the "
                "second; a sequence renders each frame once (the renderer's history carries "
                "over: accumulate reprojects, eye adaptation follows) with a progress bar on a "
                "terminal. reference mode accumulates --spp jittered samples per pixel with a "
                "progress bar on a terminal and writes linear .pfm/.exr only.");
}

namespace {

// A sequence's frame rate: above this a frame's time step (1/fps) rounds animation times.
constexpr double kMaxFps = 1e4;
// Frame numbers are padded to at most this many digits (%0Nd).
constexpr size_t kMaxFrameNumberWidth = 9;

bool isTerminal() {
    return ::isatty(::fileno(stderr)) != 0;
}

void printProgress(int done, int total, const char* unit, double elapsedS) {
    constexpr int kBarWidth = 30;
    const int filled = total > 0 ? done * kBarWidth / total : kBarWidth;
    const double left = done > 0 ? elapsedS / done * (total - done) : 0.0;
    std::fprintf(stderr, "\r[%s%s] %d/%d %s, %.1f s left  ",
                 std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(kBarWidth - filled), '.').c_str(), done, total, unit, left);
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
        if (progress) printProgress(s + 1, options.spp, "spp", secondsSince(traceStart));
    }
    writeImage(options.outputPath, reference.readMean());
    const char* method =
        reference.getMethod() == gpu::kReferenceLight ? "light tracing" : "path tracing";
    if (!options.quiet) {
        std::printf("wrote %s (%dx%d, reference, %d spp, %d bounces)\n", options.outputPath.c_str(),
                    resolveFrameSettings(settings).width, resolveFrameSettings(settings).height,
                    options.spp, reference.getBounces());
        std::printf("%s: %.1f ms; whole command: %.1f ms\n", method, secondsSince(traceStart) * 1e3,
                    secondsSince(start) * 1e3);
    }
    return checkGlErrors(method);
}

} // namespace

std::string formatFramePath(const std::string& pattern, int index, const std::string& where) {
    std::string out;
    int conversions = 0;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        // %d, %Nd or %0Nd: an optional zero flag and width, then d.
        size_t j = i + 1;
        const bool zeros = j < pattern.size() && pattern[j] == '0';
        if (zeros) ++j;
        size_t width = 0;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) &&
               width < kMaxFrameNumberWidth) {
            width = width * 10 + size_t(pattern[j] - '0');
            ++j;
        }
        if (j >= pattern.size() || pattern[j] != 'd') {
            throw InputError(strCat(where,
                                    ": expected a frame number as %d, %4d or %04d (and %% "
                                    "for a percent sign), got '",
                                    pattern, "'"));
        }
        std::string number = std::to_string(index);
        if (number.size() < width) number.insert(0, width - number.size(), zeros ? '0' : ' ');
        out += number;
        ++conversions;
        i = j;
    }
    if (conversions != 1) {
        throw InputError(strCat(where,
                                ": a sequence needs one frame number in the path (e.g. "
                                "out_%04d.png), got '",
                                pattern, "'"));
    }
    return out;
}

namespace {

// What `render` writes of the runner's last frame: the photon-buffer image (drawn by the
// command's one drawer, its programs built once), the tone-mapped frame or a linear AOV.
struct OutputImage {
    OutputKind kind;
    Aov aov;
    std::optional<PhotonAov> photonAov;
    std::string aovName;
    std::optional<PhotonPointsDrawer> drawer;

    Image read(const FrameRunner& runner) {
        if (photonAov) {
            if (!drawer) drawer.emplace();
            return drawer->renderAov(runner, *photonAov);
        }
        return readTextureImage(runner.getAov(kind == OutputKind::Png ? Aov::Display : aov));
    }
    const char* describe() const {
        return !photonAov && kind == OutputKind::Png ? "tone mapped" : aovName.c_str();
    }
};

// --frames N: the animation from --time on, a frame every 1/fps s, each written as it is done.
int runSequence(const RenderOptions& options, Scene& scene, FrameRunner& runner,
                OutputImage& output, const gl::ContextInfo& info,
                std::chrono::steady_clock::time_point start) {
    const bool progress = !options.quiet && isTerminal();
    const auto sequenceStart = std::chrono::steady_clock::now();
    std::vector<double> frameMs;
    for (int i = 0; i < options.frames; ++i) {
        const auto frameStart = std::chrono::steady_clock::now();
        if (scene.isAnimated()) {
            scene.update(options.timeS + double(i) / options.fps);
            runner.updateScene();
        }
        // The first frame has no predecessor: its white point is its own.
        runner.setPresentation({.timeStepS = i == 0 ? -1.0 : 1.0 / options.fps});
        runner.renderFrame();
        writeImage(formatFramePath(options.outputPath, i, "--output"), output.read(runner));
        frameMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart)
                .count());
        if (progress) {
            printProgress(
                i + 1, options.frames, "frames",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - sequenceStart)
                    .count());
        }
    }
    if (!options.quiet) {
        runner.waitForTimings();
        std::printf("wrote %d frames, %s to %s (%dx%d, %s; %g s to %g s at %g frames/s)\n",
                    options.frames, formatFramePath(options.outputPath, 0, "--output").c_str(),
                    formatFramePath(options.outputPath, options.frames - 1, "--output").c_str(),
                    runner.getFrameSettings().width, runner.getFrameSettings().height,
                    output.describe(), options.timeS,
                    options.timeS + double(options.frames - 1) / options.fps, options.fps);
        // The first frame builds the shaders: the median of the others is what a frame costs.
        std::vector<double> later(frameMs.begin() + (frameMs.size() > 1 ? 1 : 0), frameMs.end());
        std::nth_element(later.begin(), later.begin() + long(later.size() / 2), later.end());
        std::printf("frame with its write, median: %.1f ms; the last frame's passes:\n",
                    later[later.size() / 2]);
        printTimings(runner, info);
        std::printf("whole command: %.1f ms\n", std::chrono::duration<double, std::milli>(
                                                    std::chrono::steady_clock::now() - start)
                                                    .count());
    }
    return checkGlErrors("rendering");
}

} // namespace

int runRender(const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const OutputKind kind = classifyOutput(options.outputPath, "--output");
    if (options.frames < 1) {
        throw InputError(strCat("--frames: expected at least 1, got ", options.frames));
    }
    if (!std::isfinite(options.fps) || !(options.fps > 0.0) || options.fps > kMaxFps) {
        throw InputError(
            strCat("--fps: expected frames per second in (0, ", kMaxFps, "], got ", options.fps));
    }
    const bool isSequence = options.frames > 1;
    if (isSequence && options.mode == "reference") {
        throw InputError("--frames: reference mode renders one frame (render a sequence with "
                         "--mode ispm, or each --time with the reference)");
    }
    // Every frame of a sequence goes to the same folder: checking the first checks them all.
    checkWritableOutput(isSequence ? formatFramePath(options.outputPath, 0, "--output")
                                   : options.outputPath,
                        "--output");
    const std::optional<PhotonAov> photonAov = findPhotonAov(options.aov);
    const Aov aov = photonAov ? Aov::Display : parseAov(options.aov, "--aov");
    if (options.mode != "ispm" && options.mode != "reference") {
        throw InputError(strCat("--mode: expected ispm or reference, got '", options.mode, "'"));
    }
    const bool isReference = options.mode == "reference";
    if (photonAov && kind != OutputKind::Png) {
        throw InputError(strCat("--aov: the photon-buffer image '", options.aov,
                                "' is a display image: write .png"));
    }
    if (photonAov && options.mode != "ispm") {
        throw InputError("--aov: photon-buffer images need --mode ispm");
    }
    if (kind == OutputKind::Png && aov != Aov::Total && !photonAov) {
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
    const gl::TimingMethod timing = gl::chooseTimingMethod(context->getInfo());
    FrameRunner runner(scene, settings, timing);
    if (photonAov && !runner.getFrameSettings().hasIndirect()) {
        throw InputError(strCat("--aov: '", options.aov,
                                "' draws photons, and this frame has none (bounces and photons "
                                "must be > 0)"));
    }
    warnIfLightFades(runner);
    OutputImage output{kind, aov, photonAov, options.aov, std::nullopt};
    if (isSequence) return runSequence(options, scene, runner, output, context->getInfo(), start);
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
    writeImage(options.outputPath, output.read(runner));
    if (!options.quiet) {
        const double totalMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        std::printf("wrote %s (%dx%d, %s)\n", options.outputPath.c_str(),
                    runner.getFrameSettings().width, runner.getFrameSettings().height,
                    output.describe());
        if (accumulate > 0) {
            std::printf("indirect light: %u frames accumulated (seeds %u to %u)\n",
                        runner.getPasses().accumulate.getAccumulatedFrames(),
                        runner.getFrameSettings().seed,
                        runner.getFrameSettings().seed + uint32_t(frames) - 1);
        }
        printTimings(runner, context->getInfo());
        std::printf("whole command: %.1f ms (scene load, context, shader builds, frame, write)\n",
                    totalMs);
    }
    return checkGlErrors("rendering");
}

} // namespace ispm
