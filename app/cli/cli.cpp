// Subcommand dispatch and the error policy: bad input prints one line and exits 2, a failed check
// exits 1, anything unexpected prints its context and exits 1.
#include "cli/cli.h"

#include "cli/bench_command.h"
#include "cli/render_command.h"
#include "cli/view_command.h"
#include "core/input_error.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/timer.h"
#include "image/image_io.h"
#include "image/metrics.h"
#include "scene/scene_loader.h"
#include "settings/settings.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace ispm {
namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitCheckFailed = 1;

int runInfo() {
    auto context = gl::createHeadlessContext();
    const gl::ContextInfo& info = context->getInfo();
    std::printf("context path:  %s\n", gl::getContextPathName(info.path));
    std::printf("device:        %s\n", info.device.c_str());
    std::printf("vendor:        %s\n", info.vendor.c_str());
    std::printf("renderer:      %s%s\n", info.renderer.c_str(),
                info.isSoftware ? " (software)" : "");
    std::printf("version:       %s\n", info.version.c_str());
    std::printf("GLSL:          %s\n", info.glslVersion.c_str());
    std::printf("pass timing:   %s\n", gl::getTimingMethodName(gl::chooseTimingMethod(info)));
    for (const gl::ContextLimit& l : gl::queryContextLimits())
        std::printf("%-26s %lld\n", l.name, static_cast<long long>(l.value));
    return 0;
}

// A mask image includes the pixels where any channel is above one half (white on black).
PixelMask readMask(const std::string& path, const Image& like) {
    constexpr float kIncludedAbove = 0.5f;
    const Image mask = readImage(path);
    if (mask.width != like.width || mask.height != like.height) {
        throw InputError(strCat(path, ": expected a ", like.width, "x", like.height, " mask, got ",
                                mask.width, "x", mask.height));
    }
    PixelMask included(mask.pixels.size());
    for (size_t i = 0; i < mask.pixels.size(); ++i) {
        const glm::vec3& p = mask.pixels[i];
        included[i] = std::max({p.x, p.y, p.z}) > kIncludedAbove ? 1 : 0;
    }
    return included;
}

int runCompare(const std::string& a, const std::string& b, const std::string& minusPath,
               const std::string& maskPath, double maxRelMse) {
    // NonNegativeNumber lets nan through (nan < 0 is false), which would turn the check off.
    if (!std::isfinite(maxRelMse)) {
        throw InputError(strCat("--max-relmse: expected a finite number >= 0, got ", maxRelMse));
    }
    const Image test = readImage(a);
    Image reference = readImage(b);
    if (!minusPath.empty()) {
        const Image minus = readImage(minusPath);
        if (minus.width != reference.width || minus.height != reference.height) {
            throw InputError(strCat(minusPath, " is ", minus.width, "x", minus.height, " but ", b,
                                    " is ", reference.width, "x", reference.height,
                                    ": expected equal sizes"));
        }
        reference = subtractImages(reference, minus);
    }
    if (test.width != reference.width || test.height != reference.height) {
        throw InputError(strCat(a, " is ", test.width, "x", test.height, " but ", b, " is ",
                                reference.width, "x", reference.height, ": expected equal sizes"));
    }
    const PixelMask mask = maskPath.empty() ? PixelMask() : readMask(maskPath, test);
    const ImageMetrics m = computeMetrics(test, reference, maskPath.empty() ? nullptr : &mask);
    std::printf("pixels      %zu\n", m.pixelCount);
    std::printf("RMSE        %.6g\n", m.rmse);
    std::printf("relMSE      %.6g\n", m.relMse);
    std::printf("SSIM        %.6f\n", m.ssim);
    std::printf("mean ratio  %.6f %.6f %.6f\n", m.meanRatio.x, m.meanRatio.y, m.meanRatio.z);
    if (m.litPixelCount > 0) {
        std::printf("energy        %.6f (mean ratio over the %zu pixels not black in B)\n",
                    m.energy, m.litPixelCount);
        std::printf("rel RMSE 4x4  %.6f\n", m.relRmse4);
        std::printf("rel RMSE 1x1  %.6f\n", m.relRmse1);
    } else {
        std::printf("energy, rel RMSE: none (B is black everywhere)\n");
    }
    if (maxRelMse >= 0.0 && !(m.relMse <= maxRelMse)) {
        std::printf("FAIL: relMSE %.6g > %.6g\n", m.relMse, maxRelMse);
        return kExitCheckFailed;
    }
    return 0;
}

} // namespace

int runCli(int argc, char** argv) {
    CLI::App app{"ispm: real-time global illumination by image-space photon mapping"};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "help for every subcommand");

    RenderOptions render;
    addRenderCommand(app, render);
    BenchOptions bench;
    addBenchCommand(app, bench);
    ViewOptions view;
    addViewCommand(app, view);

    std::string exportScene;
    std::string exportOut;
    CLI::App* exportCmd = app.add_subcommand(
        "export", "Write the scene's world-space triangles as OBJ + MTL (generated geometry too)");
    exportCmd->add_option("scene", exportScene, "scene file (JSON)")->required();
    exportCmd->add_option("-o,--output", exportOut, "output .obj (the .mtl is written beside it)")
        ->required();

    CLI::App* infoCmd = app.add_subcommand(
        "info", "Print the OpenGL context: path taken, vendor, renderer, version, limits");

    CLI::App* settingsCmd = app.add_subcommand(
        "settings", "Print the user settings by group (default, range, unit, meaning) as Markdown");
    bool allSettings = false;
    settingsCmd->add_flag("--all", allSettings,
                          "every setting, advanced ones included: a table per group");

    std::string compareA;
    std::string compareB;
    double maxRelMse = -1.0;
    std::string maskPath;
    std::string minusPath;
    CLI::App* compareCmd = app.add_subcommand(
        "compare", "Compare image A against reference B: RMSE, relMSE, SSIM, mean ratio");
    compareCmd->add_option("a", compareA, "test image (.png, .pfm, .exr)")->required();
    compareCmd->add_option("b", compareB, "reference image (.png, .pfm, .exr)")->required();
    compareCmd->add_option("--max-relmse", maxRelMse, "exit 1 when relMSE exceeds this")
        ->check(CLI::NonNegativeNumber);
    compareCmd->add_option("--minus", minusPath,
                           "image subtracted from B first: B = bounces N, --minus bounces 0 "
                           "compares indirect light");
    compareCmd->add_option("--mask", maskPath,
                           "image of the same size: only pixels brighter than 0.5 are compared");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        if (argc > 1 && app.get_subcommands().empty() && argv[1][0] != '-') {
            std::fprintf(stderr,
                         "ispm: unknown subcommand '%s' (expected render, view, bench, export, "
                         "info, settings or compare; see ispm --help)\n",
                         argv[1]);
        } else {
            std::fprintf(stderr, "ispm: %s\n", e.what());
        }
        return kExitBadInput;
    }

    try {
        if (app.got_subcommand("render")) return runRender(render);
        if (app.got_subcommand("bench")) return runBench(bench);
        if (app.got_subcommand("view")) return runView(view);
        if (app.got_subcommand(exportCmd)) {
            const Scene scene = loadScene(exportScene);
            exportObj(scene, exportOut);
            std::printf("wrote %s (%zu triangles)\n", exportOut.c_str(), scene.countTriangles());
            return 0;
        }
        if (app.got_subcommand(infoCmd)) return runInfo();
        if (app.got_subcommand(settingsCmd)) {
            const std::string table =
                allSettings ? formatAllSettingsMarkdown() : formatUserSettingsMarkdown();
            std::fputs(table.c_str(), stdout);
            return 0;
        }
        if (app.got_subcommand(compareCmd))
            return runCompare(compareA, compareB, minusPath, maskPath, maxRelMse);
    } catch (const InputError& e) {
        std::fprintf(stderr, "ispm: %s\n", e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ispm: error: %s\n", e.what());
        return kExitCheckFailed;
    }
    return 0;
}

} // namespace ispm
