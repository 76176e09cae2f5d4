// The settings table and the checks every value passes on its way in.
#include "settings/settings.h"

#include "settings/setting_choices.h"

#include "core/input_error.h"
#include "core/strings.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace ispm {
namespace {

template <size_t N>
std::vector<std::string_view> toChoices(const std::array<std::string_view, N>& choices) {
    return {choices.begin(), choices.end()};
}

const std::vector<SettingDesc>& table() {
    static const std::vector<SettingDesc> kTable = {
        {"width", SettingType::Int, 512, 1, 16384, "px", "image width", {}},
        {"height", SettingType::Int, 512, 1, 16384, "px", "image height", {}},
        {"tonemap", SettingType::Enum, 0, 0, 2, "",
         "tone-map operator, after the 2^exposure scale: thesis (luminance clamped at "
         "luminance_max keeping the hue, then divided by it), filmic (ACES fit, luminance_max at "
         "97% of white), linear (each channel divided by luminance_max and clipped at 1)",
         toChoices(kToneMapChoices)},
        {"exposure",
         SettingType::Float,
         0,
         -30,
         30,
         "stops",
         "scale before tone mapping, 2^exposure",
         {}},
        {"luminance_max",
         SettingType::Float,
         0,
         1e-6,
         1e9,
         "W/(m^2 sr)",
         "luminance mapped to white (thesis and linear; filmic maps it to 97% of white); "
         "derived from the image (99th percentile of luminance) when not set",
         {},
         true},
        {"eye_adaptation_s",
         SettingType::Float,
         0,
         0,
         60,
         "s",
         "eye adaptation: time constant with which a derived luminance_max follows the image, in "
         "log luminance (63% of the way after this time); 0 = each frame its own. Time passes "
         "in render sequences (--frames, --fps) and in the viewer",
         {}},
        {"gamma",
         SettingType::Float,
         2.2,
         0.1,
         10,
         "",
         "display gamma applied after tone mapping",
         {}},
        {"shadow_map_size",
         SettingType::Int,
         1024,
         16,
         8192,
         "px",
         "resolution of every light camera's G-buffer and shadow map; derived: 1024 with "
         "shadows map, and with shadows ray (the views then only emit photons) 2 sqrt(photons) "
         "rounded up to a power of two, 256 to 1024",
         {},
         true},
        {"shadows", SettingType::Enum, 0, 0, 1, "",
         "how direct light finds its shadows: map (every light view's shadow map, the thesis's: "
         "edges follow its texels, moved by shadow_bias) or ray (a ray from every pixel to each "
         "light through the BVH, as the path tracer's: exact hard shadows; the sun's shadow-only "
         "view is not drawn)",
         toChoices(kShadowChoices)},
        {"edge_samples",
         SettingType::Int,
         0,
         0,
         256,
         "",
         "anti-aliased direct light: pixels at silhouettes, lit creases and edges of the light "
         "(a shadow's, a spot cone's) are shaded again from this many rays through points "
         "spread over the pixel (the BVH; the shadow test of shadows) and get their mean, the "
         "reference path tracer's box filter; pixels whose light changes little against their "
         "own take a half or a quarter; 0 = off (the pixel's centre alone)",
         {}},
        {"shadow_bias",
         SettingType::Float,
         1.0,
         0,
         100,
         "texels",
         "shadow-map bias (shadows map), in light-camera texels at the receiver's depth: the "
         "depth test's "
         "margin, and how far the receiver is pushed along its normal at grazing light (times "
         "the sine of the angle to the light)",
         {}},
        {"seed", SettingType::Int, 1, 0, 2147483647, "", "random seed of the frame", {}},
        {"photons",
         SettingType::Int,
         50000,
         0,
         16777216,
         "",
         "photon budget of the frame, shared among the lights (photon_share, else by power)",
         {}},
        {"frame_ms_target",
         SettingType::Float,
         0,
         0,
         1e6,
         "ms",
         "frame time to hold: the photon budget follows the measured times of the photon passes "
         "(emit, trace, density, splat) over recent frames, steps of at most 2x, changes under "
         "10% left alone, 1000 photons at least; not while a still view accumulates; 0 = off",
         {}},
        {"bounces",
         SettingType::Int,
         3,
         0,
         64, // the reference's default: --bounces reaches it in both modes
         "",
         "indirect light that reflected 1..bounces times is kept (0: direct light only)",
         {}},
        {"first_bounce", SettingType::Enum, 0, 0, 1, "",
         "the first bounce's Russian roulette (the light views' photons): roulette (the "
         "thesis's: on the surface's albedo, absorbed photons end) or weighted (among the lobes "
         "alone, by their share of the albedo, the power times it: every photon that meets a "
         "reflecting surface bounces, so the same budget sends 1 / albedo times as many on, each "
         "at the trace's cost)",
         toChoices(kFirstBounceChoices)},
        {"specular_depth",
         SettingType::Int,
         3,
         0,
         6, // each level doubles the rays a pixel may trace (a reflected and a refracted one)
         "",
         "levels of rays traced from what the camera sees in mirrors (Phong exponent >= 64) and "
         "glass: a reflected ray (the Phong lobe's and Fresnel's reflectance) and a refracted one "
         "per level, each hit shaded with direct light (shadow rays) and the indirect light of "
         "the visible pixel showing the same point (else an ambient estimate); at most `bounces` "
         "levels; 0 = off (mirrors shaded by their Phong lobe only, glass black)",
         {}},
        {"reference_method", SettingType::Enum, 0, 0, 1, "",
         "estimator of --mode reference: path (camera paths with next-event estimation to each "
         "light; cannot see a point, spot or sun light through glass or in a mirror) or light "
         "(light paths from the lights, each vertex on a diffuse or glossy surface connected to "
         "the camera: caustics converge; glass and mirrors seen by the camera stay black but "
         "for their diffuse and glossy parts)",
         toChoices(kReferenceMethodChoices)},
        {"importance",
         SettingType::Float,
         0.75,
         0,
         1,
         "",
         "share of each light view's photons aimed at what the viewer sees (its importance map); "
         "the rest follow the light's power alone (0: the thesis's uniform grid)",
         {}},
        {"importance_samples",
         SettingType::Int,
         8192,
         0,
         1048576,
         "",
         "viewer pixels that build the importance maps (each also casts one bounce ray, and one "
         "more from a point that no light reaches): all of "
         "them on a view's first frame, importance_samples / importance_frames on each later one",
         {}},
        {"importance_frames",
         SettingType::Int,
         4,
         1,
         64,
         "frames",
         "frames the importance maps average: each frame's samples are blended in with weight "
         "1 / importance_frames (an exponential average), so the maps hold about 1.75x "
         "importance_samples at 4 for a quarter of the gather; they start anew when the "
         "settings, the image size, the scene's lights or objects (added, removed) or an "
         "emitting light view change, not when the camera or the seed does (any map is an "
         "unbiased pdf: a moving view's aim lags a few frames); 1 = each frame its own maps",
         {}},
        {"rng", SettingType::Enum, 0, 0, 2, "",
         "which random numbers scatter a photon from frame to frame: fixed (keyed on the grid cell "
         "it was emitted from, so it keeps its path while nothing it meets moves; new numbers "
         "only for accumulated frames), per_frame (a new seed every frame, the thesis's "
         "prototype), object_space (each bounce keyed on where the photon hit, in the hit "
         "triangle's own coordinates, thesis 7.2)",
         toChoices(kRngModeChoices)},
        {"rng_generator", SettingType::Enum, 2, 0, 2, "",
         "random number generator: pcg (stateless hash of photon, bounce and seed), lcg (a "
         "linear congruential generator, Numerical Recipes constants) or sobol (the first "
         "bounce from an Owen-scrambled Sobol sequence over the emission grid in Z order, so "
         "neighbouring photons take stratified roulette decisions and directions; later "
         "bounces pcg)",
         toChoices(kRngGeneratorChoices)},
        {"radius_mode", SettingType::Enum, 2, 0, 2, "",
         "splat radius from travel distance (travel, the thesis), from path density alone "
         "(path_density, McGuire and Luebke 2009: radius_max / sqrt(path density), at least "
         "radius_min) or from the local density of stored photons (density: each disc holds about "
         "splat_neighbours photons; photons focused by mirrors, glass or a glossy lobe since their "
         "last diffuse bounce, caustics, hold their own kind's neighbours and are splatted at "
         "the image's resolution, unfiltered)",
         toChoices(kRadiusModeChoices)},
        {"splat_neighbours",
         SettingType::Int,
         0,
         1,
         4096,
         "",
         "radius_mode density: photons a splat disc holds in one frame; derived: 0.45 "
         "sqrt(photons), 16 to 256 (accumulated frames hold fewer, see accumulate)",
         {},
         true},
        {"splat_merge",
         SettingType::Float,
         0,
         0,
         1,
         "",
         "radius_mode density: photons whose discs would lie almost on top of each other are "
         "drawn as one disc, of their summed power at their power-weighted centre, its radius "
         "their radii's power-weighted RMS: those in one cell of side at most splat_merge x the "
         "radius (the density grid's, on the same side of a surface; caustic photons apart), so "
         "the splat draws fewer discs; 0 = every photon its own disc",
         {}},
        {"radius_min",
         SettingType::Float,
         0,
         1e-6,
         1e6,
         "m",
         "travel: splat radius at dist_min or less; path_density: the smallest radius; derived: "
         "r0 / 2, where `photons` discs of radius r0 cover the area in view 32 times (of the "
         "objects whose boxes meet the view pyramid); "
         "density: a floor when set",
         {},
         true},
        {"radius_max",
         SettingType::Float,
         0,
         1e-6,
         1e6,
         "m",
         "travel: splat radius at dist_max or more; path_density: the radius of a photon whose "
         "path never focused (diffuse bounces only); derived: 2 r0; density: the largest radius, "
         "derived: 4 r0 with r0 for splat_neighbours discs",
         {},
         true},
        {"dist_min",
         SettingType::Float,
         0,
         0,
         1e9,
         "m",
         "radius_mode travel: travel distance where the radius starts to grow; derived: 0",
         {},
         true},
        {"dist_max",
         SettingType::Float,
         0,
         1e-6,
         1e9,
         "m",
         "radius_mode travel: travel distance where the radius reaches radius_max; derived: the "
         "scene's diagonal",
         {},
         true},
        {"radius_scale",
         SettingType::Float,
         1,
         1e-3,
         1e3,
         "",
         "multiplies every splat radius (derived or set)",
         {}},
        {"squash",
         SettingType::Float,
         0.1,
         1e-3,
         1,
         "",
         "splat ellipsoid thickness along the surface normal, as a fraction of its radius",
         {}},
        {"splat_passes",
         SettingType::Int,
         1,
         1,
         64,
         "",
         "number of draw calls the splats are split into",
         {}},
        {"splat_resolution", SettingType::Enum, 0, 0, 3, "",
         "resolution of the splat buffer against the image: 1, 1/2 or 1/4, upsampled by a "
         "joint-bilateral filter on the viewer G-buffer (normals, planes, reflectance); auto: "
         "1/2 from 256 px on (min(width, height)), else 1; caustics (radius_mode density) are "
         "splatted at 1",
         toChoices(kSplatResolutionChoices)},
        {"denoise",
         SettingType::Int,
         0,
         0,
         8,
         "",
         "iterations of an edge-aware a-trous filter on the indirect light (steps of 1, 2, 4 ... "
         "pixels of the splat buffer, guided by normals and planes of the viewer G-buffer; not "
         "the caustics of radius_mode density); 0 = the splats as they are; derived: log2(min(w, "
         "h) / 32) of the splat buffer's size, at "
         "most 3 (2 at 256 px with the splats at 1/2)",
         {},
         true},
        {"accumulate",
         SettingType::Int,
         0,
         0,
         65536,
         "frames",
         "temporal accumulation of the light: each frame traces new photons (seed + frame); while "
         "the camera, the scene and the settings stay as they are, it looks through new sub-pixel "
         "and light-texel offsets, with splat radii and filter shrinking as frames add up, and is "
         "averaged in, up to this many frames; then the image holds and frames cost nothing; when "
         "the camera or objects move, the indirect light's history is reprojected (kept where the "
         "same surface shows, at most this many frames a pixel) and the direct light's restarts; "
         "a changed light or setting starts again; 0 = off (each frame alone)",
         {}},
        {"splat_mode", SettingType::Enum, 0, 0, 1, "",
         "how result photons reach the image: raster (each drawn as an instanced splat of "
         "splat_shape, the thesis's method) or gather (binned on the GPU into 8x8-pixel tiles "
         "by the projected box of their splat, each pixel summing its tile's photons with the "
         "same kernel, normal and clip tests: the image of splat_shape box up to float "
         "round-off)",
         toChoices(kSplatModeChoices)},
        {"splat_shape", SettingType::Enum, 0, 0, 1, "",
         "what each photon's splat rasterises: disc (a flat square round its disc in its surface "
         "plane, cut where walls cut the disc) or box (the cube of the thesis, squashed along the "
         "normal to squash x the radius; ispm draws its back faces only, so each covered pixel is "
         "shaded once); "
         "the fragment stage tests the same ellipsoid in both, so the images differ only on "
         "surfaces off the photon's plane but inside the box",
         toChoices(kSplatShapeChoices)},
        {"splat_clip", SettingType::Enum, 0, 0, 2, "",
         "discs cut where other surfaces meet their plane (shared/splat_clip.h): the density pass "
         "casts eight rays in each photon's surface plane (one BVH box query round its disc) and "
         "keeps the lines where walls and the surface's own edges cross it; the splat draws the "
         "photon's side of every line and divides each pixel's share by the part of its own disc "
         "inside them, so light neither leaks through a thin wall nor fades at a wall's foot; "
         "auto: on with radius_mode density, off with travel and path_density (the thesis's "
         "whole discs: no query, but through a wall 2 cm thick they leak 29% and 40% of the "
         "light beside it); on costs 1-7 us a photon in view in the density pass (wider discs "
         "meet more triangles) and a dearer splat on llvmpipe (Cornell box, 25,000 travel discs, "
         "128x128: 143 -> 199 ms)",
         toChoices(kSplatClipChoices)},
        {"surface_ends", SettingType::Enum, 0, 0, 2, "",
         "discs without clip lines (splat_clip off): each photon's power is divided by the share "
         "of its disc a surface can hold, as the viewer G-buffer shows it: 8 points of the disc "
         "are looked up, and where the eye sees past one (the background, or a surface farther "
         "than the point: beyond a wall's top or side, through a door) it counts as off the "
         "surface, so a disc reaching past a wall's edge into the air keeps its light on the "
         "wall (courtyard outside, the house's front: indirect light 0.72-0.75 -> 0.96-0.99 of "
         "the reference); hidden points, points off the image and a wall's foot count as on; "
         "auto: on with radius_mode density, off with travel and path_density (the thesis's "
         "whole discs); costs about 0.45 ms in the density pass for 7,600 photons in view "
         "(llvmpipe)",
         toChoices(kSurfaceEndsChoices)},
        {"widen_strong", SettingType::Enum, 0, 0, 1, "",
         "radius_mode travel and path_density: a photon stronger than its light's mean this frame "
         "is drawn sqrt(power / mean) times wider (at most 2x), so that it spreads its power "
         "instead of making a bright spot, as the density radii spread a photon stronger than its "
         "neighbours (importance sampling's floor sends photons with up to 1 / (1 - importance) "
         "times the power they would carry unaimed, 4x at the default); weaker photons keep "
         "their radius; off = the radii as derived",
         toChoices(kWidenStrongChoices)},
        // Post-processing (linear HDR, between compose and tone map): each off by default, and
        // with all three off no post pass runs.
        {"motion_blur_shutter",
         SettingType::Float,
         0,
         0,
         1,
         "frames",
         "motion blur: how long the shutter is open, as a fraction of a frame; each pixel's light "
         "is spread evenly along its screen motion since the last frame (the G-buffer's velocity "
         "channel: objects' and the camera's motion), centred on it, at most 64 px; energy "
         "kept; 0 = off",
         {}},
        {"dof_aperture_m",
         SettingType::Float,
         0,
         0,
         10,
         "m",
         "depth blur: diameter of a thin lens; each pixel's light is spread evenly over its "
         "circle of confusion, A abs(1/d - 1/dof_focus_m) H / (2 tan(fovY / 2)) pixels across at "
         "depth d (H the image height; the focal length cancels for a given field of view), "
         "radius at most 16 px; energy kept; 0 = off (a pinhole)",
         {}},
        {"dof_focus_m",
         SettingType::Float,
         0,
         1e-3,
         1e6,
         "m",
         "depth blur: distance along the view axis that is in focus; derived: the depth of the "
         "surface at the image centre, read on the GPU each frame (infinitely far where the "
         "centre shows no surface)",
         {},
         true},
        {"bloom_intensity",
         SettingType::Float,
         0,
         0,
         1,
         "",
         "bloom: share of the light above bloom_threshold that is spread around its pixel by a "
         "Gaussian (the rest stays), so the image's energy is kept; 0 = off",
         {}},
        {"bloom_threshold",
         SettingType::Float,
         1,
         0,
         1e9,
         "W/(m^2 sr)",
         "bloom: luminance (0.3 R + 0.6 G + 0.1 B, before exposure) above which light blooms; "
         "a pixel gives the part of its radiance above it, hue kept (compare luminance_max, "
         "which render prints)",
         {}},
        {"bloom_radius_px",
         SettingType::Float,
         16,
         1,
         64,
         "px",
         "bloom: reach of the Gaussian, 3 standard deviations",
         {}},
    };
    return kTable;
}

} // namespace

std::span<const SettingDesc> getSettingTable() {
    return table();
}

const SettingDesc* findSetting(std::string_view name) {
    for (const SettingDesc& d : table()) {
        if (d.name == name) return &d;
    }
    return nullptr;
}

namespace {

// Whole numbers in full (2147483647, not 2.14748365e+09), others as strCat writes them.
std::string formatNumber(double value) {
    constexpr double kLargestExact = 9007199254740992.0; // 2^53
    if (value == std::floor(value) && std::abs(value) < kLargestExact) {
        return std::to_string(static_cast<long long>(value));
    }
    return strCat(value);
}

std::string describeType(const SettingDesc& d) {
    switch (d.type) {
    case SettingType::Int:
        return "int";
    case SettingType::Float:
        return "float";
    case SettingType::Enum:
        return "enum";
    }
    return "";
}

} // namespace

std::string formatSettingsMarkdown() {
    std::string out = "| name | type | default | range | unit | meaning |\n";
    out += "|---|---|---|---|---|---|\n";
    for (const SettingDesc& d : table()) {
        std::string defaultText;
        std::string range;
        if (d.type == SettingType::Enum) {
            defaultText = strCat("`", d.choices.at(static_cast<size_t>(d.defaultValue)), "`");
            for (std::string_view c : d.choices)
                range += (range.empty() ? "" : ", ") + strCat("`", c, "`");
        } else {
            defaultText = d.derived ? "derived" : formatNumber(d.defaultValue);
            range = strCat(formatNumber(d.minValue), " to ", formatNumber(d.maxValue));
        }
        out += strCat("| `", d.name, "` | ", describeType(d), " | ", defaultText, " | ", range,
                      " | ", d.unit, " | ", d.help, " |\n");
    }
    return out;
}

static const SettingDesc& requireSetting(std::string_view name, const std::string& where) {
    const SettingDesc* desc = findSetting(name);
    if (!desc) {
        std::string known;
        for (const SettingDesc& d : table())
            known += (known.empty() ? "" : ", ") + std::string(d.name);
        throw InputError(strCat(where, ": unknown setting '", name, "' (known: ", known, ")"));
    }
    return *desc;
}

void Settings::set(std::string_view name, double value, const std::string& where) {
    const SettingDesc& desc = requireSetting(name, where);
    if (!std::isfinite(value) || value < desc.minValue || value > desc.maxValue) {
        throw InputError(strCat(where, ": expected ", desc.name, " in [", desc.minValue, ", ",
                                desc.maxValue, "], got ", value));
    }
    if (desc.type != SettingType::Float && value != std::floor(value)) {
        throw InputError(strCat(where, ": expected an integer for ", desc.name, ", got ", value));
    }
    mValues[std::string(name)] = value;
}

void Settings::setEnum(std::string_view name, std::string_view choice, const std::string& where) {
    const SettingDesc& desc = requireSetting(name, where);
    if (desc.type != SettingType::Enum) {
        throw InputError(strCat(where, ": expected a number for ", name, ", got '", choice, "'"));
    }
    auto it = std::find(desc.choices.begin(), desc.choices.end(), choice);
    if (it == desc.choices.end()) {
        std::string options;
        for (std::string_view c : desc.choices)
            options += (options.empty() ? "" : "|") + std::string(c);
        throw InputError(
            strCat(where, ": expected ", name, " to be one of ", options, ", got '", choice, "'"));
    }
    mValues[std::string(name)] = static_cast<double>(it - desc.choices.begin());
}

void Settings::setFromString(std::string_view assignment, const std::string& where) {
    const size_t eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        throw InputError(strCat(where, ": expected name=value, got '", assignment, "'"));
    }
    const std::string_view name = assignment.substr(0, eq);
    const std::string_view text = assignment.substr(eq + 1);
    const SettingDesc& desc = requireSetting(name, where);
    if (desc.type == SettingType::Enum) {
        setEnum(name, text, where);
        return;
    }
    double value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size() || text.empty()) {
        throw InputError(strCat(where, ": expected a number for ", name, ", got '", text, "'"));
    }
    set(name, value, where);
}

bool Settings::isSet(std::string_view name) const {
    return mValues.find(name) != mValues.end();
}

double Settings::get(std::string_view name) const {
    auto it = mValues.find(name);
    if (it != mValues.end()) return it->second;
    const SettingDesc* desc = findSetting(name);
    if (!desc) throw std::logic_error(strCat("no setting named '", name, "'"));
    return desc->defaultValue;
}

std::string_view Settings::getEnum(std::string_view name) const {
    const SettingDesc* desc = findSetting(name);
    if (!desc || desc->type != SettingType::Enum) {
        throw std::logic_error(strCat("'", name, "' is not an enum setting"));
    }
    return desc->choices.at(static_cast<size_t>(get(name)));
}

void Settings::merge(const Settings& other) {
    for (const auto& [name, value] : other.mValues)
        mValues[name] = value;
}

nlohmann::json formatRenderBlock(const Settings& settings) {
    nlohmann::json block = nlohmann::json::object();
    for (const auto& [name, value] : settings.getOverrides()) {
        const SettingDesc* d = findSetting(name);
        if (!d) continue; // set() admits table names only
        switch (d->type) {
        case SettingType::Enum:
            block[name] = std::string(settings.getEnum(name));
            break;
        case SettingType::Int:
            block[name] = static_cast<int64_t>(value);
            break;
        case SettingType::Float:
            block[name] = value;
            break;
        }
    }
    return block;
}

} // namespace ispm
