// Resolving the settings table into FrameSettings, with the derived values.
#include "settings/frame_settings.h"

#include <shared/gather_data.h>
#include <shared/light_trace_data.h>
#include <shared/photon_data.h>
#include <shared/photon_scatter.h>
#include <shared/scene_data.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace ispm {
namespace {

// The shaders compare against these constants; the settings table lists its choices in this
// order (settings.cpp builds them from the arrays in setting_choices.h).
static_assert(kToneMapChoices[gpu::kTonemapThesis] == "thesis");
static_assert(kToneMapChoices[gpu::kTonemapFilmic] == "filmic");
static_assert(kToneMapChoices[gpu::kTonemapLinear] == "linear");
static_assert(kFirstBounceChoices[gpu::kFirstBounceRoulette] == "roulette" &&
              kFirstBounceChoices[gpu::kFirstBounceWeighted] == "weighted");
static_assert(kRngGeneratorChoices[gpu::kRngPcg] == "pcg" &&
              kRngGeneratorChoices[gpu::kRngLcg] == "lcg" &&
              kRngGeneratorChoices[gpu::kRngSobol] == "sobol");
static_assert(kRngModeChoices[gpu::kRngFixed] == "fixed" &&
              kRngModeChoices[gpu::kRngPerFrame] == "per_frame" &&
              kRngModeChoices[gpu::kRngObjectSpace] == "object_space");
static_assert(kReferenceMethodChoices[gpu::kReferencePath] == "path" &&
              kReferenceMethodChoices[gpu::kReferenceLight] == "light");
static_assert(kSplatModeChoices[gpu::kSplatModeRaster] == "raster" &&
              kSplatModeChoices[gpu::kSplatModeGather] == "gather");
static_assert(kShadowChoices[gpu::kShadowsMap] == "map" &&
              kShadowChoices[gpu::kShadowsRay] == "ray");
static_assert(kSplatShapeChoices[gpu::kSplatShapeDisc] == "disc" &&
              kSplatShapeChoices[gpu::kSplatShapeBox] == "box");
static_assert(kRadiusModeChoices[gpu::kRadiusTravel] == "travel");
static_assert(kRadiusModeChoices[gpu::kRadiusPathDensity] == "path_density");
static_assert(kRadiusModeChoices[gpu::kRadiusDensity] == "density");
static_assert(kSplatResolutionChoices[0] == "auto" && kSplatResolutionChoices[2] == "1/2" &&
              kSplatResolutionChoices[3] == "1/4");

// Photons a splat disc holds by default: enough that one photon's noise averages out over its
// neighbours' (relative noise ~ 1 / sqrt(k)), few enough to keep detail. k grows with the budget
// as sqrt(photons), so more photons buy both less noise and sharper light: 101 at 50,000 photons.
// One frame's noise against its blur. Medians over eight seeds at 256x256, 50,000 photons, rel
// RMSE of Cornell / courtyard outside / room, with sobol first bounces and each block's area
// from its photons' span: 0.127 / 0.263 / 0.221 at k 44 (0.2 sqrt(photons)), 0.123 / 0.252 /
// 0.215 at 56, 0.121 / 0.247 / 0.207 at 67, 0.117 / 0.236 / 0.203 at 89; the average of the
// eight seeds (the bias) stays 0.081 / 0.14 / 0.15 throughout. Before the span, wider discs
// lost light in concave corners (a block there counted air as area): the Cornell box's pixels
// within 2 cm of an edge got 0.95 of the middle's light at 64, 0.93 at 90; with it they get
// 1.0 at 67 and 89 (FailureModeTest.CornersAndEdgesLoseIndirectEnergy). 89 leaves 0.7% of the
// Cornell box's pixels dark at 2,000 photons (FailureModeTest.SparsePhotonsLeaveUncoveredPixels
// holds 0.5%), 67 leaves 0.09%. With flat splats (splat_shape disc) the worst of eight seeds
// decides: 0.128 / 0.268 / 0.281 at 67, 0.123 / 0.252 / 0.256 at 100, 0.121 / 0.245 / 0.250 at
// 130 (medians 0.120 / 0.247 / 0.207, 0.115 / 0.229 / 0.202, 0.113 / 0.224 / 0.203), the
// corners at 1.0 of the middle still; 0.45 sqrt(photons) (101) costs the splat about 1.4x of 67.
// Accumulated frames hold fewer (computeProgressiveStep): their average takes the noise down,
// the blur stays.
constexpr double kNeighboursPerSqrtPhoton = 0.45;
constexpr int kMinNeighbours = 16;
constexpr int kMaxNeighbours = 256;

// splat_resolution auto: half resolution from this image size on. The splat's cost follows its
// fragments (Cornell box, 50,000 photons: 174 ms at 128 px, 460 at 256, 1,420 at 512 on
// llvmpipe), and its light varies over several pixels from 256 px on, where the filter and the
// upsample keep the error at full resolution's (docs/results.md, "Frame times on llvmpipe").
constexpr int kHalfResolutionFromPx = 256;

// Image size whose derived filter is one iteration wide (steps of 1 pixel, +-2 pixels): at
// 256 px three iterations reach +-14 pixels, about 5% of the image, where the splats' noise is.
constexpr double kPixelsPerIteration = 32.0;
// At most three derived iterations: each costs 25 taps a pixel (1.2 s at 1280x1024 for five on
// llvmpipe); larger images keep the filter's reach in pixels, not in image fractions.
constexpr int kMaxDerivedIterations = 3;

// shadow_map_size when not set. Shadow maps need fine texels: the box city's streets at 128x128
// gained shadow-edge pixels lit against the reference's black at 512 (relMSE 0.13 -> 6.7 of its
// direct light), so with shadows map every view keeps 1024. With shadows ray the views only emit
// photons (from the texels their importance samples fall in), and their size hardly moves the
// error at 128x128, 10,000 photons (relMSE at 1024 / 512 / 256: courtyard outside 0.0205 /
// 0.0188 / 0.0208, Cornell box 0.0225 / 0.0225 / 0.0223, room 0.0450 / 0.0451 / 0.0403; room
// indirect light over eight seeds at 25,000 photons with shadow maps: 0.074 / 0.079 / 0.075),
// while the views' cost follows their texels (room: 32.8 ms at 1024, 10.0 at 512, 3.2 at 256 on
// llvmpipe). Twice the emission grid's side (sqrt(photons) over all views) keeps about four
// texels a photon.
constexpr int kShadowMapTexels = 1024;
constexpr double kEmissionTexelsPerGridCell = 2.0;
constexpr int kMinEmissionTexels = 256;

std::optional<float> getIfSet(const Settings& settings, std::string_view name) {
    return settings.isSet(name) ? std::optional<float>(settings.getFloat(name)) : std::nullopt;
}

uint32_t getChoice(const Settings& settings, std::string_view name) {
    return static_cast<uint32_t>(settings.get(name));
}

} // namespace

int computeSplatNeighbours(const Settings& settings) {
    return computeSplatNeighbours(settings, settings.get("photons"));
}

int computeSplatNeighbours(const Settings& settings, double photons) {
    if (settings.isSet("splat_neighbours")) return settings.getInt("splat_neighbours");
    const double k = kNeighboursPerSqrtPhoton * std::sqrt(std::max(photons, 0.0));
    return std::clamp(int(std::lround(k)), kMinNeighbours, kMaxNeighbours);
}

int computeSplatDivisor(const Settings& settings, int width, int height) {
    // Choices "auto", "1", "1/2", "1/4": choice i > 0 divides by 2^(i - 1).
    const uint32_t choice = getChoice(settings, "splat_resolution");
    if (choice > 0) return 1 << (choice - 1);
    return std::min(width, height) >= kHalfResolutionFromPx ? 2 : 1;
}

glm::ivec2 computeSplatSize(const Settings& settings, int width, int height) {
    const int divisor = computeSplatDivisor(settings, width, height);
    return {(width + divisor - 1) / divisor, (height + divisor - 1) / divisor};
}

bool computeSplatClip(const Settings& settings) {
    // Choices "auto", "on", "off": auto clips the density radii's discs, not the travel modes'.
    const uint32_t choice = getChoice(settings, "splat_clip");
    if (choice == 0) return getChoice(settings, "radius_mode") == gpu::kRadiusDensity;
    return choice == 1;
}

bool computeSurfaceEnds(const Settings& settings) {
    if (computeSplatClip(settings)) return false;
    // Choices "auto", "on", "off": auto for the density radii's discs, not the travel modes'.
    const uint32_t choice = getChoice(settings, "surface_ends");
    if (choice == 0) return getChoice(settings, "radius_mode") == gpu::kRadiusDensity;
    return choice == 1;
}

int computeShadowMapSize(const Settings& settings) {
    return computeShadowMapSize(settings, settings.get("photons"));
}

int computeShadowMapSize(const Settings& settings, double photons) {
    if (settings.isSet("shadow_map_size")) return settings.getInt("shadow_map_size");
    if (getChoice(settings, "shadows") != gpu::kShadowsRay) return kShadowMapTexels;
    const auto wanted = static_cast<unsigned>(
        std::ceil(kEmissionTexelsPerGridCell * std::sqrt(std::max(photons, 0.0))));
    return std::clamp(static_cast<int>(std::bit_ceil(wanted)), kMinEmissionTexels,
                      kShadowMapTexels);
}

int computeDenoiseIterations(const Settings& settings, int width, int height) {
    if (settings.isSet("denoise")) return settings.getInt("denoise");
    const double iterations = std::log2(double(std::min(width, height)) / kPixelsPerIteration);
    return std::clamp(int(std::lround(iterations)), 0, kMaxDerivedIterations);
}

FrameSettings resolveFrameSettings(const Settings& settings) {
    FrameSettings f;
    f.width = settings.getInt("width");
    f.height = settings.getInt("height");
    f.toneMap = getChoice(settings, "tonemap");
    f.exposureStops = settings.getFloat("exposure");
    f.gamma = settings.getFloat("gamma");
    f.luminanceMax = getIfSet(settings, "luminance_max");
    f.eyeAdaptationS = settings.getFloat("eye_adaptation_s");
    f.shadowMapSize = computeShadowMapSize(settings);
    f.shadowBiasTexels = settings.getFloat("shadow_bias");
    f.shadows = getChoice(settings, "shadows");
    f.edgeSamples = settings.getInt("edge_samples");
    f.areaSamples = settings.getInt("area_samples");
    f.seed = static_cast<uint32_t>(settings.getInt("seed"));
    f.photons = settings.getInt("photons");
    f.frameMsTarget = settings.getFloat("frame_ms_target");
    f.bounces = settings.getInt("bounces");
    f.specularDepth = settings.getInt("specular_depth");
    f.bouncesSet = settings.isSet("bounces");
    f.referenceMethod = getChoice(settings, "reference_method");
    f.importanceSamples = settings.getInt("importance_samples");
    f.importanceFrames = settings.getInt("importance_frames");
    f.importance = f.importanceSamples > 0 ? settings.getFloat("importance") : 0.0f;
    f.rngGenerator = getChoice(settings, "rng_generator");
    f.firstBounce = getChoice(settings, "first_bounce");
    f.rngMode = getChoice(settings, "rng");
    f.radiusMode = getChoice(settings, "radius_mode");
    f.splatNeighbours = computeSplatNeighbours(settings);
    f.splatMerge = settings.getFloat("splat_merge");
    f.radiusMinM = getIfSet(settings, "radius_min");
    f.radiusMaxM = getIfSet(settings, "radius_max");
    f.distMinM = getIfSet(settings, "dist_min");
    f.distMaxM = getIfSet(settings, "dist_max");
    f.radiusScale = settings.getFloat("radius_scale");
    f.squash = settings.getFloat("squash");
    f.splatPasses = settings.getInt("splat_passes");
    f.splatShape = getChoice(settings, "splat_shape");
    f.splatMode = getChoice(settings, "splat_mode");
    f.splatClip = computeSplatClip(settings);
    f.surfaceEnds = computeSurfaceEnds(settings);
    // The density radii spread strong photons by their neighbours already.
    f.widenStrong = getChoice(settings, "widen_strong") == 1 && f.radiusMode != gpu::kRadiusDensity;
    f.splatDivisor = computeSplatDivisor(settings, f.width, f.height);
    f.splatSize = computeSplatSize(settings, f.width, f.height);
    f.denoiseIterations = computeDenoiseIterations(settings, f.splatSize.x, f.splatSize.y);
    f.accumulate = settings.getInt("accumulate");
    f.motionBlurShutter = settings.getFloat("motion_blur_shutter");
    f.dofApertureM = settings.getFloat("dof_aperture_m");
    f.dofFocusM = getIfSet(settings, "dof_focus_m");
    f.bloomIntensity = settings.getFloat("bloom_intensity");
    f.bloomThreshold = settings.getFloat("bloom_threshold");
    f.bloomRadiusPx = settings.getFloat("bloom_radius_px");
    return f;
}

void applyPhotonBudget(FrameSettings& frame, const Settings& settings, int photons) {
    frame.photons = photons;
    frame.splatNeighbours = computeSplatNeighbours(settings, photons);
    frame.shadowMapSize = computeShadowMapSize(settings, photons);
}

} // namespace ispm
