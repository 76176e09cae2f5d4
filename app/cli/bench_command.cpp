// Bench command: warm up, time N frames pass by pass, and report per-pass medians (with min and
// max), the median frame total, peak memory and the effective settings. Speed is measured here,
// not in timed tests.
#include "cli/bench_command.h"

#include "cli/bench_flicker.h"
#include "cli/bench_stats.h"
#include "cli/bench_sweep.h"
#include "cli/cli_common.h"
#include "core/input_error.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/state.h"
#include "gl/timer.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"

#include <shared/photon_data.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

namespace ispm {
namespace {

constexpr int kMinTimedFrames = 1;   // a median needs at least one sample
constexpr int kMinFlickerFrames = 2; // a standard deviation needs two

constexpr int kMinWarmupFrames = 0;
constexpr double kBytesPerMib = 1024.0 * 1024.0;
// --animate: the time step of a 60 Hz display, so the motion per frame is what a viewer sees.
constexpr double kAnimateFrameSeconds = 1.0 / 60.0;
constexpr const char* kSceneUpdateRow = "scene update";

struct PresetSetting {
    const char* name;
    double value;
};

// The thesis benchmark: McLaughlin's box city at 1280x1024 with 50k photons and three bounces,
// rendered the thesis's way: a uniform grid per light view (no importance), splat radii from
// travel distance, no filter after the splats, direct light at pixel centres (no edge samples).
// The splats are drawn at half the image's
// resolution and upsampled on the G-buffer (McGuire and Luebke's remedy for the splat's cost,
// which the thesis names in 7.2): against the path tracer the indirect light's error is the
// same as at full resolution (rel RMSE 4x4 1.080 against 1.085), the frame a fifth cheaper.
constexpr const char* kThesisPresetName = "thesis";
constexpr const char* kThesisScene = "scenes/box_city.json"; // under ISPM_ASSET_DIR
constexpr double kSplatHalfResolution = 2;                   // splat_resolution's choice "1/2"
constexpr PresetSetting kThesisSettings[] = {
    {"width", 1280},    {"height", 1024},
    {"photons", 50000}, {"bounces", 3},
    {"importance", 0},  {"radius_mode", gpu::kRadiusTravel},
    {"denoise", 0},     {"splat_resolution", kSplatHalfResolution},
    {"edge_samples", 0}};

// Preset settings that name no entry in the settings table (yet) are skipped and reported, so the
// preset keeps its meaning as the photon pipeline's settings arrive.
struct PresetResult {
    Settings settings;
    std::vector<std::string> applied; // "name=value"
    std::vector<std::string> skipped; // names
};

PresetResult applyThesisPreset() {
    PresetResult result;
    for (const PresetSetting& s : kThesisSettings) {
        if (findSetting(s.name)) {
            result.settings.set(s.name, s.value, strCat("--preset ", kThesisPresetName));
            const SettingDesc& desc = *findSetting(s.name);
            result.applied.push_back(
                desc.type == SettingType::Enum
                    ? strCat(s.name, "=", desc.choices.at(static_cast<size_t>(s.value)))
                    : strCat(s.name, "=", s.value));
        } else {
            result.skipped.push_back(s.name);
        }
    }
    return result;
}

// Photon counts of the last timed frame; none when the frame has no indirect light (bounces = 0
// or photons = 0), rather than zeros that would read as measured.
std::optional<PhotonCounts> readReportedPhotonCounts(const FrameRunner& runner) {
    const PhotonCounts counts = readPhotonCounts(runner);
    if (counts.emitted == 0) return std::nullopt;
    return counts;
}

struct BenchReport {
    std::string scenePath;
    int width = 0;
    int height = 0;
    int frames = 0;
    int warmup = 0;
    std::string renderer;
    std::string contextPath;
    std::string timingMethod;
    bool animate = false;
    std::vector<PassStats> passes; // frame order
    PassStats total;               // sum of the passes, per frame
    std::optional<double> peakRssMib;
    size_t glBytes = 0;
    std::optional<PhotonCounts> photons;
    nlohmann::json settings; // effective overrides: enums by name, integers as integers
    std::string presetName;
    PresetResult preset;
    std::optional<FlickerResult> flicker;
};

void printJson(const BenchReport& r) {
    nlohmann::json out;
    out["scene"] = r.scenePath;
    out["width"] = r.width;
    out["height"] = r.height;
    out["frames"] = r.frames;
    out["warmup"] = r.warmup;
    out["renderer"] = r.renderer;
    out["timing_method"] = r.timingMethod;
    out["animate"] = r.animate;
    out["passes"] = nlohmann::json::array();
    for (const PassStats& p : r.passes) {
        out["passes"].push_back({{"name", p.name},
                                 {"median_ms", p.medianMs},
                                 {"min_ms", p.minMs},
                                 {"max_ms", p.maxMs}});
    }
    out["total_median_ms"] = r.total.medianMs;
    out["peak_rss_mib"] = r.peakRssMib ? nlohmann::json(*r.peakRssMib) : nlohmann::json(nullptr);
    out["gl_bytes"] = r.glBytes;
    if (r.photons) {
        out["photons"] = {
            {"emitted", r.photons->emitted},   {"bounced", r.photons->bounced},
            {"stored", r.photons->stored},     {"stored_in_view", r.photons->inView},
            {"overflow", r.photons->overflow}, {"per_light", nlohmann::json::array()}};
        for (const LightCounts& l : r.photons->perLight) {
            out["photons"]["per_light"].push_back({{"emitted", l.emitted},
                                                   {"bounced", l.bounced},
                                                   {"stored", l.stored},
                                                   {"stored_in_view", l.inView}});
        }
    }
    if (r.flicker) {
        out["flicker"] = {{"frames", r.flicker->frames}, {"all", r.flicker->all},
                          {"away", r.flicker->away},     {"away_m", r.flicker->awayM},
                          {"pixels", r.flicker->pixels}, {"away_pixels", r.flicker->awayPixels}};
    }
    out["settings"] = r.settings;
    if (!r.presetName.empty()) {
        out["preset"] = {
            {"name", r.presetName}, {"applied", r.preset.applied}, {"skipped", r.preset.skipped}};
    }
    std::printf("%s\n", out.dump(2).c_str());
}

std::string joinWords(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words)
        out += (out.empty() ? "" : " ") + w;
    return out;
}

void printText(const BenchReport& r) {
    std::printf("bench %s: %dx%d, %d timed frames after %d warm-up\n", r.scenePath.c_str(), r.width,
                r.height, r.frames, r.warmup);
    std::printf("renderer: %s (%s); pass times by %s\n", r.renderer.c_str(), r.contextPath.c_str(),
                r.timingMethod.c_str());
    if (r.animate) {
        std::printf("animated: %.4f s per frame; '%s' = Scene::update + top-level BVH rebuild + "
                    "light cameras + uploads (CPU clock)\n",
                    kAnimateFrameSeconds, kSceneUpdateRow);
    }
    if (!r.presetName.empty()) {
        std::printf("preset %s: applied %s", r.presetName.c_str(),
                    r.preset.applied.empty() ? "nothing" : joinWords(r.preset.applied).c_str());
        if (!r.preset.skipped.empty()) {
            std::printf("; skipped (not in the settings table): %s",
                        joinWords(r.preset.skipped).c_str());
        }
        std::printf("\n");
    }
    std::string settings;
    for (const auto& [name, value] : r.settings.items()) {
        settings += strCat(settings.empty() ? "" : " ", name, "=",
                           value.is_string() ? value.get<std::string>() : value.dump());
    }
    std::printf("settings: %s\n", settings.empty() ? "(defaults)" : settings.c_str());
    std::printf("  %-12s %10s %10s %10s\n", "pass", "median ms", "min ms", "max ms");
    for (const PassStats& p : r.passes) {
        std::printf("  %-12s %10.2f %10.2f %10.2f\n", p.name.c_str(), p.medianMs, p.minMs, p.maxMs);
    }
    std::printf("  %-12s %10.2f %10.2f %10.2f\n", "total", r.total.medianMs, r.total.minMs,
                r.total.maxMs);
    if (r.photons) {
        std::printf("photons: emitted %u, after the first bounce %u, stored %u (%u in view), "
                    "overflow %u\n",
                    r.photons->emitted, r.photons->bounced, r.photons->stored, r.photons->inView,
                    r.photons->overflow);
        for (size_t i = 0; i < r.photons->perLight.size(); ++i) {
            const LightCounts& l = r.photons->perLight[i];
            std::printf(
                "  light %zu: emitted %u, after the first bounce %u, stored %u (%u in view)\n", i,
                l.emitted, l.bounced, l.stored, l.inView);
        }
    }
    const std::string rss = r.peakRssMib ? strCat(static_cast<int64_t>(*r.peakRssMib + 0.5), " MiB")
                                         : std::string("unknown");
    std::printf("memory: peak RSS %s, GL allocations %.1f MiB (%zu bytes)\n", rss.c_str(),
                static_cast<double>(r.glBytes) / kBytesPerMib, r.glBytes);
    if (r.flicker) {
        std::printf("flicker over %d frames (mean temporal std of the indirect light / its mean): "
                    "all %zu surface pixels %.5f; the %zu farther than %.2f m from moving objects "
                    "%.5f\n",
                    r.flicker->frames, r.flicker->pixels, r.flicker->all, r.flicker->awayPixels,
                    r.flicker->awayM, r.flicker->away);
    }
}

// Every input is checked before any GL work: bad values exit 2 without creating a context.
void checkOptions(const BenchOptions& options) {
    if (options.frames < kMinTimedFrames) {
        throw InputError(
            strCat("--frames: expected an integer >= ", kMinTimedFrames, ", got ", options.frames));
    }
    if (options.warmup < kMinWarmupFrames) {
        throw InputError(strCat("--warmup: expected an integer >= ", kMinWarmupFrames, ", got ",
                                options.warmup));
    }
    if (!options.preset.empty() && options.preset != kThesisPresetName) {
        throw InputError(
            strCat("--preset: expected '", kThesisPresetName, "', got '", options.preset, "'"));
    }
    if (options.scenePath.empty() && options.preset.empty()) {
        throw InputError("bench: expected a scene file (SCENE may be left out only with --preset)");
    }
    if (options.flickerFrames && *options.flickerFrames < kMinFlickerFrames) {
        throw InputError(strCat("--flicker: expected an integer >= ", kMinFlickerFrames, ", got ",
                                *options.flickerFrames));
    }
    if (!std::isfinite(options.flickerAwayM) || options.flickerAwayM < 0.0) {
        throw InputError(strCat("--flicker-away: expected a distance >= 0 in metres, got ",
                                options.flickerAwayM));
    }
    if (options.flickerFrames && isSweepRequested(options)) {
        throw InputError("--flicker: expected without --sweep/--reference/--csv");
    }
    if (options.rounds != 1 && !isSweepRequested(options)) {
        throw InputError("--rounds: expected only with --sweep (a sweep's passes over its "
                         "configurations)");
    }
    if (options.animate && isSweepRequested(options)) {
        throw InputError("--animate: expected without --sweep/--reference/--csv (a sweep compares "
                         "still frames with a reference)");
    }
}

// Advances the scene to `timeS` and re-uploads what moved; returns the milliseconds it took,
// after glFinish so that uploads are counted here and not in the first pass.
double advanceAnimation(Scene& scene, FrameRunner& runner, double timeS) {
    const auto start = std::chrono::steady_clock::now();
    scene.update(timeS);
    runner.updateScene();
    gl::finish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// The scene update's row goes first (it runs before the passes) and counts in the frame total.
void addSceneUpdateTime(double ms, FrameTimes& times) {
    auto [it, inserted] = times.samplesMs.try_emplace(kSceneUpdateRow);
    if (inserted) times.passOrder.insert(times.passOrder.begin(), kSceneUpdateRow);
    it->second.push_back(ms);
    times.totalsMs.back() += ms;
}

} // namespace

void addBenchCommand(CLI::App& app, BenchOptions& options) {
    CLI::App* cmd = app.add_subcommand("bench", "Time every pass over many frames of a scene");
    cmd->add_option("scene", options.scenePath,
                    "scene file (JSON); optional with --preset, which then supplies it");
    addCameraOption(*cmd, options.cameraName);
    cmd->add_option("--frames", options.frames, "timed frames, >= 1 (default 10)");
    cmd->add_option("--warmup", options.warmup,
                    "untimed frames first, >= 0 (default 2: first use of a program is slow)");
    cmd->add_option("--width", options.width, "image width in pixels (setting `width`)");
    cmd->add_option("--height", options.height, "image height in pixels (setting `height`)");
    cmd->add_option("--set", options.sets, "override a setting: name=value (repeatable)");
    cmd->add_flag("--json", options.json, "print one JSON object on stdout and nothing else");
    cmd->add_flag("--animate", options.animate,
                  "advance animated scenes by 1/60 s per frame and time the scene update (BVH "
                  "top level, light cameras) as a row of its own");
    cmd->add_option("--flicker", options.flickerFrames,
                    "time N frames and measure their flicker: the mean over surface pixels of the "
                    "temporal standard deviation of the indirect light, divided by its mean, for "
                    "all pixels and for those farther than --flicker-away from moving objects");
    cmd->add_option("--flicker-away", options.flickerAwayM,
                    "--flicker: metres from any moving object's box beyond which a pixel counts as "
                    "away (default 0.5)");
    cmd->add_option("--preset", options.preset,
                    "benchmark configuration: thesis (box city, 1280x1024, photons=50000, "
                    "bounces=3)");
    cmd->footer(
        "Renders the warm-up frames, then the timed frames, and prints per pass (in frame order) "
        "the median, min and max milliseconds and the median frame total (sum of the passes), the "
        "timing method, the renderer, the image size, the peak RSS of the process and the bytes "
        "of GL allocations.\n"
        "Settings are layered: the scene's `render` block, then the preset, then --set, then "
        "--width/--height. --preset thesis uses assets/scenes/box_city.json unless SCENE is given; "
        "preset settings the settings table does not know yet are skipped and listed.\n"
        "--json fields: scene, width, height, frames, warmup, renderer, timing_method, animate, "
        "passes "
        "[{name, median_ms, min_ms, max_ms}], total_median_ms, peak_rss_mib, gl_bytes, settings, "
        "photons {emitted, bounced, stored, stored_in_view, overflow, per_light [{emitted, "
        "bounced, stored, stored_in_view}]} when the frame has indirect light, "
        "and preset {name, applied, skipped} with --preset.\n"
        "Sweep mode (--sweep, --reference, --csv): renders every configuration of the sweeps' "
        "cartesian product (values checked by the settings table; the render size must be the "
        "reference's) and runs the path tracer with the same bounces to --reference-spp-max "
        "samples, a share of its samples after each configuration, so that both are timed over "
        "the same stretch of the run; with --rounds N it passes over the configurations N times "
        "(the tracer's samples spread over all of them) and takes each one's medians over its "
        "frames of every round, so that the machine's slow spells weigh on all alike. Timed frame "
        "i of a configuration draws with seed + i (its "
        "importance maps built anew, as in a moving view) and its errors are the mean over the "
        "timed frames: the expected error of one frame. The path tracer draws with seed + 2^30, "
        "not the samples of a reference rendered with the same seed. The CSV has one row per "
        "configuration (kind=ispm: the settings, median ms per pass, total_ms, relmse_total, "
        "relmse_indirect, ssim, photon counts) and one per 1, 2, 4, ... spp (kind=reference: "
        "cumulative total_ms). "
        "relmse_indirect compares ispm's indirect AOV with REF minus ispm's own direct AOV (both "
        "shade direct light alike up to shadow-map edges), or with REF minus --reference-direct. "
        "Prints the equal-error speedup per configuration; tools/plot_bench.py draws the CSV.");
    cmd->add_option("--sweep", options.sweeps,
                    "sweep a setting: name=v1,v2,... (repeatable; the product is rendered)");
    cmd->add_option("--reference", options.referencePath,
                    "sweep: converged reference image (.pfm/.exr, linear, same size)");
    cmd->add_option("--reference-direct", options.referenceDirectPath,
                    "sweep: bounces=0 reference (.pfm/.exr) for relmse_indirect");
    cmd->add_option("--csv", options.csvPath, "sweep: output CSV");
    cmd->add_option("--reference-spp-max", options.referenceSppMax,
                    "sweep: last sample count of the path tracer's curve (default 64)");
    cmd->add_option("--rounds", options.rounds,
                    "sweep: passes over every configuration, each timing its --frames again (the "
                    "medians over all rounds; the errors from the first; default 1)");
}

int runBench(const BenchOptions& options) {
    checkOptions(options);
    BenchReport report;
    report.presetName = options.preset;
    report.scenePath = options.scenePath;
    if (report.scenePath.empty()) {
        report.scenePath = (std::filesystem::path(ISPM_ASSET_DIR) / kThesisScene).string();
    }
    if (!options.preset.empty()) report.preset = applyThesisPreset();
    const Settings commandLine =
        makeCommandLineSettings(options.sets, options.width, options.height);
    Scene scene = loadScene(report.scenePath);
    selectCamera(scene, options.cameraName);
    Settings settings = scene.settings;
    settings.merge(report.preset.settings);
    settings.merge(commandLine);
    if (isSweepRequested(options)) return runBenchSweep(options, report.scenePath, scene, settings);
    report.settings = formatRenderBlock(settings);

    auto context = gl::createHeadlessContext();
    const gl::ContextInfo& info = context->getInfo();
    const gl::TimingMethod timing = gl::chooseTimingMethod(info);
    FrameRunner runner(scene, settings, timing);
    warnIfLightFades(runner);
    int frameIndex = 0;
    // Frame i shows time i/60 s: warm-up frames animate too, so the timed ones are not the first
    // to rebuild anything.
    auto advance = [&]() {
        const double timeS = static_cast<double>(frameIndex++) * kAnimateFrameSeconds;
        return options.animate ? advanceAnimation(scene, runner, timeS) : 0.0;
    };
    for (int i = 0; i < options.warmup; ++i) {
        advance();
        runner.renderFrame();
    }

    FrameTimes times;
    const int frames = options.flickerFrames.value_or(options.frames);
    std::optional<FlickerMeter> flicker;
    if (options.flickerFrames) flicker.emplace(options.flickerAwayM);
    for (int i = 0; i < frames; ++i) {
        const double updateMs = advance();
        runner.renderFrame();
        runner.waitForTimings(); // this frame's, not an earlier one's
        addFrameTimes(runner, times);
        if (options.animate) addSceneUpdateTime(updateMs, times);
        if (flicker) {
            flicker->addFrame(
                readTextureImage(runner.getAov(Aov::Indirect)),
                readTextureTopDown(runner.getPasses().gbuffer.getGBuffer().getChannel("position")),
                scene);
        }
    }
    if (flicker) report.flicker = flicker->getResult();

    report.width = runner.getFrameSettings().width;
    report.height = runner.getFrameSettings().height;
    report.frames = frames;
    report.warmup = options.warmup;
    report.renderer = info.renderer;
    report.contextPath = gl::getContextPathName(info.path);
    report.timingMethod = gl::getTimingMethodName(runner.getTimings().method);
    report.animate = options.animate;
    for (const std::string& name : times.passOrder) {
        report.passes.push_back(computeStats(name, times.samplesMs[name]));
    }
    report.total = computeStats("total", times.totalsMs);
    report.peakRssMib = readPeakRssMib();
    report.glBytes = computeGpuBytes(runner);
    report.photons = readReportedPhotonCounts(runner);

    if (options.json) {
        printJson(report);
    } else {
        printText(report);
    }
    return checkGlErrors("benchmarking");
}

} // namespace ispm
