// Bench sweeps: every configuration of the sweeps' cartesian product is timed and compared with the
// reference, then the path tracer's own error-against-time curve is measured in the same process,
// so both sides share the machine, the context and the load. One CSV holds both (column `kind`).
#include "cli/bench_sweep.h"

#include "cli/bench_options.h"
#include "cli/cli_common.h"
#include "core/input_error.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/state.h"
#include "gl/timer.h"
#include "image/image_io.h"
#include "image/metrics.h"
#include "render/readback.h"
#include "render/reference_pass.h"
#include "settings/frame_settings.h"

#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <utility>

namespace ispm {
namespace {

constexpr int kMinReferenceSpp = 1;
// Settings every row names, swept or not: the image size, the light the image holds, and the two
// knobs of the photon mapper's speed/accuracy trade (budget and splat size).
constexpr const char* kAlwaysColumns[] = {"width", "height", "bounces", "photons", "radius_scale"};
// Settings that change the path tracer's image; reference rows leave the other columns empty.
constexpr const char* kReferenceSettings[] = {"width", "height", "bounces", "seed"};
// Log-log interpolation needs positive errors; a relMSE of exactly 0 is clamped to this.
constexpr double kMinLogError = 1e-30;
constexpr int kProgressBarWidth = 30;
// The path tracer's curve draws with seed + 2^30: its sample k with the reference's own seed is the
// reference's sample k, and a curve nested in the reference reads sigma^2/N - sigma^2/R instead of
// sigma^2/N + sigma^2/R (the courtyard at 128x128: 0.0050 at 128 spp against 0.0074 drawn apart).
constexpr int64_t kTracerSeedOffset = int64_t(1) << 30;
constexpr int64_t kSeedCount = int64_t(1) << 31; // the setting's range, 0 to 2^31 - 1

// `settings` with seed (its own + `offset`) wrapped into the setting's range.
Settings offsetSeed(Settings settings, int64_t offset) {
    const int64_t seed = (static_cast<int64_t>(settings.get("seed")) + offset) % kSeedCount;
    settings.set("seed", static_cast<double>(seed), "bench sweep");
    return settings;
}

struct Sweep {
    std::string name;
    std::vector<std::string> values; // as given; each checked by the settings table
};

struct Configuration {
    Settings settings; // effective: the bench's settings with this configuration's sweep values
    std::string label; // "photons=10000 radius_scale=0.5", for the console
};

struct IspmResult {
    std::map<std::string, double> passMs; // median per pass
    double totalMs = 0.0;                 // median frame total
    double relMseTotal = 0.0;
    double relMseIndirect = 0.0;
    double ssim = 0.0;
    PhotonCounts photons;
};

struct ReferenceRow {
    int spp = 0;
    double timeMs = 0.0; // cumulative over the samples
    double relMseTotal = 0.0;
    std::optional<double> relMseIndirect; // only with --reference-direct
    double ssim = 0.0;
};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        items.push_back(text.substr(start, comma - start));
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

std::vector<Sweep> parseSweeps(const std::vector<std::string>& args) {
    std::vector<Sweep> sweeps;
    for (const std::string& arg : args) {
        const std::string where = "--sweep " + arg;
        const size_t eq = arg.find('=');
        if (eq == std::string::npos || eq == 0) {
            throw InputError(strCat(where, ": expected name=value,value,..."));
        }
        Sweep sweep{arg.substr(0, eq), splitList(arg.substr(eq + 1))};
        Settings probe; // validates name and values now, before any GL work
        for (const std::string& value : sweep.values) {
            probe.setFromString(strCat(sweep.name, "=", value), where);
        }
        for (const Sweep& other : sweeps) {
            if (other.name == sweep.name) {
                throw InputError(strCat(where, ": ", sweep.name, " is swept twice"));
            }
        }
        sweeps.push_back(std::move(sweep));
    }
    return sweeps;
}

std::string formatSetting(const Settings& settings, const std::string& name) {
    const SettingDesc* desc = findSetting(name);
    assert(desc);
    if (desc->type == SettingType::Enum) return std::string(settings.getEnum(name));
    if (desc->type == SettingType::Int) return strCat(static_cast<int64_t>(settings.get(name)));
    return strCat(settings.get(name));
}

// The cartesian product, first sweep outermost (an odometer over the value lists).
std::vector<Configuration> buildConfigurations(const Settings& base,
                                               const std::vector<Sweep>& sweeps) {
    std::vector<Configuration> configs;
    std::vector<size_t> digits(sweeps.size(), 0);
    while (true) {
        Configuration config{base, ""};
        for (size_t i = 0; i < sweeps.size(); ++i) {
            const std::string& name = sweeps[i].name;
            config.settings.setFromString(strCat(name, "=", sweeps[i].values[digits[i]]),
                                          "--sweep " + name);
            config.label +=
                strCat(i == 0 ? "" : " ", name, "=", formatSetting(config.settings, name));
        }
        if (config.label.empty()) config.label = "(one configuration)";
        configs.push_back(std::move(config));
        size_t i = sweeps.size();
        while (i > 0 && ++digits[i - 1] == sweeps[i - 1].values.size())
            digits[--i] = 0;
        if (i == 0) return configs;
    }
}

Image readReference(const std::string& path, const std::string& flag) {
    if (!isLinearImageFormat(getImageFormatFromPath(path))) {
        throw InputError(strCat(flag, " ", path, ": expected linear radiance (.pfm or .exr)"));
    }
    return readImage(path);
}

// The render size must be the reference's: a sweep over width or height gets its own message,
// since there every value has to match.
void checkRenderSizes(const std::vector<Configuration>& configs, const std::vector<Sweep>& sweeps,
                      const Image& reference, const std::string& referencePath) {
    for (const Sweep& sweep : sweeps) {
        if (sweep.name != "width" && sweep.name != "height") continue;
        const int expected = sweep.name == "width" ? reference.width : reference.height;
        for (const Configuration& c : configs) {
            if (c.settings.getInt(sweep.name) != expected) {
                throw InputError(strCat("--sweep ", sweep.name,
                                        ": every value must equal the "
                                        "reference's ",
                                        sweep.name, " ", expected, " (", referencePath, " is ",
                                        reference.width, "x", reference.height, "), got ",
                                        c.settings.getInt(sweep.name)));
            }
        }
    }
    const FrameSettings s = resolveFrameSettings(configs.front().settings);
    if (s.width != reference.width || s.height != reference.height) {
        throw InputError(strCat("--reference ", referencePath, ": the reference is ",
                                reference.width, "x", reference.height, " but the render is ",
                                s.width, "x", s.height, " (pass --width ", reference.width,
                                " --height ", reference.height, ")"));
    }
}

std::string toColumnName(const std::string& passName) {
    std::string out;
    for (const char c : passName) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0;
        out += keep ? static_cast<char>(std::tolower(static_cast<unsigned char>(c))) : '_';
    }
    return out + "_ms";
}

// One bar across the whole sweep (ispm frames and path-tracer samples as steps) on a terminal;
// nothing at all when stderr is a file or a pipe, so logs and scripts stay clean.
class SweepProgress {
  public:
    explicit SweepProgress(int totalSteps)
        : mTotal(totalSteps), mEnabled(::isatty(STDERR_FILENO) != 0),
          mStart(std::chrono::steady_clock::now()) {}

    void advance(const std::string& what) {
        ++mDone;
        if (!mEnabled) return;
        const double elapsedS =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
        const double leftS = elapsedS / mDone * (mTotal - mDone);
        const int filled = mDone * kProgressBarWidth / mTotal;
        // "\033[K" clears what a longer previous line left behind.
        std::fprintf(stderr, "\r[%s%s] %3d%% %s, %.1f s left\033[K",
                     std::string(size_t(filled), '#').c_str(),
                     std::string(size_t(kProgressBarWidth - filled), '.').c_str(),
                     100 * mDone / mTotal, what.c_str(), leftS);
        if (mDone == mTotal) std::fprintf(stderr, "\n");
    }

  private:
    int mTotal;
    int mDone = 0;
    bool mEnabled;
    std::chrono::steady_clock::time_point mStart;
};

// One round of a configuration: its warm-up frames, then its timed frames, whose pass times go
// to `times` (all rounds' frames, for the medians). With `result` the errors of the timed frames
// and the photon counts go there (the first round: later ones draw the same frames again).
void measureConfiguration(FrameRunner& runner, const Configuration& config, int warmup, int frames,
                          const Image& reference, const std::optional<Image>& referenceIndirect,
                          SweepProgress& progress, const std::string& step, FrameTimes& times,
                          IspmResult* result) {
    // Timed frame i draws with seed + i, the warm-up frames with seeds after those. The errors are
    // the mean over the timed frames, the expected error of one frame rather than one draw of it
    // (at 10,000 photons one frame's indirect relMSE in the courtyard ranged 0.0066-0.0147 over
    // five seeds), and every frame builds its importance maps anew, as in a moving view.
    for (int i = 0; i < warmup; ++i) {
        runner.setSettings(offsetSeed(config.settings, frames + i));
        runner.renderFrame();
        progress.advance(step);
    }
    for (int i = 0; i < frames; ++i) {
        runner.setSettings(offsetSeed(config.settings, i));
        runner.renderFrame();
        runner.waitForTimings(); // this frame's, not an earlier one's
        addFrameTimes(runner, times);
        if (!result) {
            progress.advance(step);
            continue;
        }
        IspmResult& r = *result;
        // Read back after the timing: not part of the frame.
        const Image total = readTextureImage(runner.getAov(Aov::Total));
        const Image indirect = readTextureImage(runner.getAov(Aov::Indirect));
        // Without --reference-direct, the reference's indirect light is the reference minus
        // ispm's own direct AOV: both shade direct light exactly (up to shadow-map edges), so the
        // difference isolates the indirect part. A path-traced bounces=0 image removes the
        // shadow-map edges too.
        const Image indirectReference =
            referenceIndirect
                ? *referenceIndirect
                : subtractImages(reference, readTextureImage(runner.getAov(Aov::Direct)));
        r.relMseTotal += computeRelMse(total, reference) / frames;
        r.relMseIndirect += computeRelMse(indirect, indirectReference) / frames;
        r.ssim += computeSsim(total, reference) / frames;
        progress.advance(step);
    }
    if (result) result->photons = readPhotonCounts(runner);
}

// The path tracer with the sweep's light (bounces) and size: rows at 1, 2, 4, ... spp and at the
// last sample, with the time of the samples alone (read-back and metrics are not counted). Its
// samples are taken a few at a time between the ispm configurations (addSamplesUpTo), spread
// over the run, so that both sides of each equal-error speedup see the same machine: on a shared
// machine speed drifts by tens of percent over minutes, and a curve timed after every
// configuration made the speedups follow the drift (a chart's best point moved from 79x to 104x
// between two runs of the same binary).
class ReferenceCurve {
  public:
    ReferenceCurve(const Scene& scene, const Settings& settings, int warmup, int sppMax,
                   const Image& reference, const std::optional<Image>& referenceDirect,
                   SweepProgress& progress)
        : mTracer(scene, settings), mSppMax(sppMax), mReference(reference),
          mReferenceDirect(referenceDirect), mProgress(progress) {
        // First use of the program is slow on llvmpipe; a throw-away pass absorbs it, as the
        // warm-up frames do for ispm (docs/design.md "The test renderer (llvmpipe)").
        ReferencePass warm(scene, settings);
        for (int i = 0; i < warmup; ++i) {
            warm.addSample();
            gl::finish();
            mProgress.advance("path tracer warm-up");
        }
    }

    // Traces samples until `spp` are in (at most --reference-spp-max).
    void addSamplesUpTo(int spp) {
        while (mSpp < std::min(spp, mSppMax)) {
            const auto start = std::chrono::steady_clock::now();
            mTracer.addSample();
            gl::finish(); // dispatches block on llvmpipe; on a GPU this makes the clock honest
            mElapsedMs +=
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            ++mSpp;
            mProgress.advance(strCat("path tracer ", mSpp, "/", mSppMax, " spp"));
            if (mSpp == mNextRow || mSpp == mSppMax) addRow();
        }
    }

    const std::vector<ReferenceRow>& getRows() const { return mRows; }

  private:
    void addRow() {
        mNextRow *= 2;
        const Image mean = mTracer.readMean();
        ReferenceRow row{mSpp, mElapsedMs, computeRelMse(mean, mReference), std::nullopt,
                         computeSsim(mean, mReference)};
        if (mReferenceDirect) {
            row.relMseIndirect = computeRelMse(subtractImages(mean, *mReferenceDirect),
                                               subtractImages(mReference, *mReferenceDirect));
        }
        mRows.push_back(row);
    }

    ReferencePass mTracer;
    int mSppMax;
    const Image& mReference;
    const std::optional<Image>& mReferenceDirect;
    SweepProgress& mProgress;
    std::vector<ReferenceRow> mRows;
    double mElapsedMs = 0.0;
    int mSpp = 0;
    int mNextRow = 1;
};

struct SweepPlan {
    std::vector<Sweep> sweeps;
    std::vector<Configuration> configs;
    Image reference;
    std::optional<Image> referenceDirect;
    Settings tracerSettings;
};

// Every check of the sweep's inputs, before any GL work: bad input exits 2 without a context.
SweepPlan planSweep(const BenchOptions& options, const Settings& settings) {
    if (options.json) {
        throw InputError("--json: a sweep writes its results to --csv; leave --json out");
    }
    if (options.referencePath.empty()) throw InputError("--sweep: expected --reference REF.pfm");
    if (options.csvPath.empty()) throw InputError("--sweep: expected --csv OUT.csv");
    if (options.rounds < 1) {
        throw InputError(strCat("--rounds: expected an integer >= 1, got ", options.rounds));
    }
    if (options.referenceSppMax < kMinReferenceSpp) {
        throw InputError(strCat("--reference-spp-max: expected an integer >= ", kMinReferenceSpp,
                                ", got ", options.referenceSppMax));
    }
    SweepPlan plan;
    plan.sweeps = parseSweeps(options.sweeps);
    plan.configs = buildConfigurations(settings, plan.sweeps);
    plan.reference = readReference(options.referencePath, "--reference");
    checkRenderSizes(plan.configs, plan.sweeps, plan.reference, options.referencePath);
    if (!options.referenceDirectPath.empty()) {
        plan.referenceDirect = readReference(options.referenceDirectPath, "--reference-direct");
        if (plan.referenceDirect->width != plan.reference.width ||
            plan.referenceDirect->height != plan.reference.height) {
            throw InputError(strCat("--reference-direct ", options.referenceDirectPath, ": is ",
                                    plan.referenceDirect->width, "x", plan.referenceDirect->height,
                                    ", expected the reference's ", plan.reference.width, "x",
                                    plan.reference.height));
        }
    }
    // The path tracer shows the same light as the ispm runs: their `bounces` (the largest when
    // bounces is swept, since the reference image can hold only one).
    int bounces = 0;
    for (const Configuration& c : plan.configs)
        bounces = std::max(bounces, resolveFrameSettings(c.settings).bounces);
    plan.tracerSettings = offsetSeed(settings, kTracerSeedOffset);
    plan.tracerSettings.set("bounces", bounces, "bench sweep");
    return plan;
}

// Columns: kind, spp, the settings, one per pass, then time, errors and photon counts. Empty cells
// are quantities a row does not have (no passes for the path tracer, no spp for ispm).
void writeCsv(std::ofstream& csv, const SweepPlan& plan, const std::vector<IspmResult>& results,
              const std::vector<std::string>& passOrder, const std::vector<ReferenceRow>& curve) {
    std::vector<std::string> settingColumns(std::begin(kAlwaysColumns), std::end(kAlwaysColumns));
    for (const Sweep& sweep : plan.sweeps) {
        if (std::find(settingColumns.begin(), settingColumns.end(), sweep.name) ==
            settingColumns.end()) {
            settingColumns.push_back(sweep.name);
        }
    }
    const std::set<std::string> tracerColumns(std::begin(kReferenceSettings),
                                              std::end(kReferenceSettings));
    csv << "kind,spp";
    for (const std::string& name : settingColumns)
        csv << "," << name;
    for (const std::string& pass : passOrder)
        csv << "," << toColumnName(pass);
    csv << ",total_ms,relmse_total,relmse_indirect,ssim,photons_emitted,photons_bounced,"
           "photons_stored,photons_overflow\n";
    for (size_t i = 0; i < results.size(); ++i) {
        const IspmResult& r = results[i];
        csv << "ispm,";
        for (const std::string& name : settingColumns) {
            csv << "," << formatSetting(plan.configs[i].settings, name);
        }
        for (const std::string& pass : passOrder) {
            const auto it = r.passMs.find(pass);
            csv << "," << (it == r.passMs.end() ? "" : strCat(it->second)); // pass skipped
        }
        csv << "," << strCat(r.totalMs) << "," << strCat(r.relMseTotal) << ","
            << strCat(r.relMseIndirect) << "," << strCat(r.ssim) << ",";
        // No photons (bounces = 0 or photons = 0): empty cells, not zeros that read as measured.
        if (r.photons.emitted == 0) {
            csv << ",,,\n";
        } else {
            csv << r.photons.emitted << "," << r.photons.bounced << "," << r.photons.stored << ","
                << r.photons.overflow << "\n";
        }
    }
    for (const ReferenceRow& row : curve) {
        csv << "reference," << row.spp;
        for (const std::string& name : settingColumns) {
            csv << ","
                << (tracerColumns.count(name) ? formatSetting(plan.tracerSettings, name) : "");
        }
        for (size_t p = 0; p < passOrder.size(); ++p)
            csv << ",";
        csv << "," << strCat(row.timeMs) << "," << strCat(row.relMseTotal) << ","
            << (row.relMseIndirect ? strCat(*row.relMseIndirect) : "") << "," << strCat(row.ssim)
            << ",,,,\n";
    }
}

std::string formatFixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

std::string formatBound(EqualErrorTime::Kind kind) {
    switch (kind) {
    case EqualErrorTime::Kind::Beyond:
        return "> ";
    case EqualErrorTime::Kind::BeforeStart:
        return "< ";
    case EqualErrorTime::Kind::Interpolated:
        break;
    }
    return "";
}

void printSpeedups(const SweepPlan& plan, const std::vector<IspmResult>& results,
                   const std::vector<ReferenceRow>& rows) {
    std::vector<CurvePoint> curve;
    for (const ReferenceRow& row : rows)
        curve.push_back({row.timeMs, row.relMseTotal});
    size_t labelWidth = std::string("configuration").size();
    for (const Configuration& c : plan.configs)
        labelWidth = std::max(labelWidth, c.label.size());
    const int w = static_cast<int>(labelWidth);
    std::printf("\nequal-error speedup = path-tracer time to reach ispm's relMSE (total, log-log "
                "interpolation along its curve) / ispm frame time\n");
    std::printf("  %-*s %10s %10s %7s %14s %10s\n", w, "configuration", "frame ms", "relMSE",
                "SSIM", "tracer ms", "speedup");
    double bestSpeedup = 0.0;
    size_t best = 0;
    EqualErrorTime::Kind bestKind = EqualErrorTime::Kind::Interpolated;
    for (size_t i = 0; i < results.size(); ++i) {
        const IspmResult& r = results[i];
        const EqualErrorTime eq = findEqualErrorTime(curve, r.relMseTotal);
        const double speedup = eq.timeMs / r.totalMs;
        const std::string bound = formatBound(eq.kind);
        const char* note = eq.kind == EqualErrorTime::Kind::Beyond        ? "  beyond the curve"
                           : eq.kind == EqualErrorTime::Kind::BeforeStart ? "  above 1 spp"
                                                                          : "";
        std::printf("  %-*s %10.2f %10.4g %7.4f %14s %10s%s\n", w, plan.configs[i].label.c_str(),
                    r.totalMs, r.relMseTotal, r.ssim, (bound + formatFixed(eq.timeMs, 1)).c_str(),
                    (bound + formatFixed(speedup, 2) + "x").c_str(), note);
        if (speedup > bestSpeedup) {
            bestSpeedup = speedup;
            best = i;
            bestKind = eq.kind;
        }
    }
    const char* qualifier = bestKind == EqualErrorTime::Kind::Beyond        ? "at least "
                            : bestKind == EqualErrorTime::Kind::BeforeStart ? "at most "
                                                                            : "";
    std::printf("best equal-error speedup: %s%.2fx (%s: %.2f ms per frame, relMSE %.4g)\n",
                qualifier, bestSpeedup, plan.configs[best].label.c_str(), results[best].totalMs,
                results[best].relMseTotal);
    if (bestKind == EqualErrorTime::Kind::Beyond) {
        std::printf("(the path tracer did not reach that error within its curve; raise "
                    "--reference-spp-max for a tighter bound)\n");
    }
}

} // namespace

bool isSweepRequested(const BenchOptions& options) {
    return !options.sweeps.empty() || !options.referencePath.empty() || !options.csvPath.empty();
}

EqualErrorTime findEqualErrorTime(const std::vector<CurvePoint>& curve, double relMse) {
    assert(!curve.empty());
    if (curve.front().relMse < relMse) return {EqualErrorTime::Kind::BeforeStart, curve[0].timeMs};
    if (curve.front().relMse == relMse)
        return {EqualErrorTime::Kind::Interpolated, curve[0].timeMs};
    for (size_t j = 1; j < curve.size(); ++j) {
        if (curve[j].relMse > relMse) continue;
        // The first crossing: curve[j - 1] is above the error, curve[j] at or below it.
        const CurvePoint& a = curve[j - 1];
        const CurvePoint& b = curve[j];
        const double logE = std::log(std::max(relMse, kMinLogError));
        const double logA = std::log(std::max(a.relMse, kMinLogError));
        const double logB = std::log(std::max(b.relMse, kMinLogError));
        const double f = logA == logB ? 1.0 : (logE - logA) / (logB - logA);
        const double logT = std::log(a.timeMs) + f * (std::log(b.timeMs) - std::log(a.timeMs));
        return {EqualErrorTime::Kind::Interpolated, std::exp(logT)};
    }
    return {EqualErrorTime::Kind::Beyond, curve.back().timeMs};
}

int runBenchSweep(const BenchOptions& options, const std::string& scenePath, const Scene& scene,
                  const Settings& settings) {
    const SweepPlan plan = planSweep(options, settings);
    std::ofstream csv(options.csvPath);
    if (!csv) throw InputError(strCat("--csv ", options.csvPath, ": cannot open for writing"));

    auto context = gl::createHeadlessContext();
    const gl::ContextInfo& info = context->getInfo();
    const gl::TimingMethod timing = gl::chooseTimingMethod(info);
    const int configCount = static_cast<int>(plan.configs.size());
    std::printf("bench sweep %s: %dx%d, %d configurations x (%d warm-up + %d timed frames)%s; "
                "path tracer to %d spp, bounces=%d\n",
                scenePath.c_str(), plan.reference.width, plan.reference.height, configCount,
                options.warmup, options.frames,
                options.rounds > 1 ? strCat(" x ", options.rounds, " rounds").c_str() : "",
                options.referenceSppMax, resolveFrameSettings(plan.tracerSettings).bounces);
    std::printf("renderer: %s (%s); pass times by %s\n", info.renderer.c_str(),
                gl::getContextPathName(info.path), gl::getTimingMethodName(timing));
    std::printf(
        "indirect reference: %s\n",
        plan.referenceDirect
            ? strCat(options.referencePath, " - ", options.referenceDirectPath).c_str()
            : strCat(options.referencePath, " - ispm's direct AOV of each configuration").c_str());
    std::fflush(stdout); // before the progress bar starts drawing on stderr

    SweepProgress progress(options.rounds * configCount * (options.warmup + options.frames) +
                           options.warmup + options.referenceSppMax);
    std::optional<Image> referenceIndirect;
    if (plan.referenceDirect)
        referenceIndirect = subtractImages(plan.reference, *plan.referenceDirect);
    FrameRunner runner(scene, plan.configs.front().settings, timing);
    ReferenceCurve tracer(scene, plan.tracerSettings, options.warmup, options.referenceSppMax,
                          plan.reference, plan.referenceDirect, progress);
    std::vector<IspmResult> results(static_cast<size_t>(configCount));
    std::vector<FrameTimes> times(static_cast<size_t>(configCount));
    std::vector<std::string> passOrder; // union over the configurations, first appearance first
    const int64_t steps = int64_t(options.rounds) * configCount;
    for (int round = 0; round < options.rounds; ++round) {
        for (int i = 0; i < configCount; ++i) {
            const Configuration& config = plan.configs[size_t(i)];
            const std::string step = strCat(
                "ispm ", i + 1, "/", configCount,
                options.rounds > 1 ? strCat(" (round ", round + 1, ")") : "", " ", config.label);
            measureConfiguration(runner, config, options.warmup, options.frames, plan.reference,
                                 referenceIndirect, progress, step, times[size_t(i)],
                                 round == 0 ? &results[size_t(i)] : nullptr);
            for (const PassTiming& t : runner.getTimings().passes) {
                if (std::find(passOrder.begin(), passOrder.end(), t.name) == passOrder.end()) {
                    passOrder.push_back(t.name);
                }
            }
            // The tracer's share of samples after each configuration: spread evenly over the
            // run.
            const int64_t done = int64_t(round) * configCount + i + 1;
            tracer.addSamplesUpTo(int(done * options.referenceSppMax / steps));
        }
    }
    for (int i = 0; i < configCount; ++i) {
        for (const auto& [name, samples] : times[size_t(i)].samplesMs)
            results[size_t(i)].passMs[name] = computeMedian(samples);
        results[size_t(i)].totalMs = computeMedian(times[size_t(i)].totalsMs);
    }
    tracer.addSamplesUpTo(options.referenceSppMax);
    const std::vector<ReferenceRow>& curve = tracer.getRows();

    writeCsv(csv, plan, results, passOrder, curve);
    csv.close();
    if (!csv) throw std::runtime_error(strCat(options.csvPath, ": write failed"));
    std::printf("wrote %s: %zu ispm rows, %zu path-tracer rows (1 to %d spp)\n",
                options.csvPath.c_str(), results.size(), curve.size(), curve.back().spp);
    printSpeedups(plan, results, curve);

    return checkGlErrors("benchmarking");
}

} // namespace ispm
