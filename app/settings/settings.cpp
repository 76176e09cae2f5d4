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

// Help strings are one line each (kMaxSettingHelpChars): what the setting does and its choices.
// Why a default is what it is, and what each choice costs, is in docs/settings.md.
const std::vector<SettingDesc>& table() {
    using enum SettingGroup;
    using enum SettingType;
    constexpr SettingLevel kUser = SettingLevel::User;
    constexpr SettingLevel kAdvanced = SettingLevel::Advanced;
    constexpr bool kDerived = true;
    static const std::vector<SettingDesc> kTable = {
        // Image.
        {"width", Image, kUser, Int, 512, 1, 16384, "px", "image width", {}},
        {"height", Image, kUser, Int, 512, 1, 16384, "px", "image height", {}},
        {"seed",
         Image,
         kAdvanced,
         Int,
         1,
         0,
         2147483647,
         "",
         "random seed of the frame: photon paths, importance samples, edge samples",
         {}},
        // Lights and shadows.
        {"shadows", Lights, kUser, Enum, 0, 0, 1, "",
         "how direct light finds its shadows: map (each light view's shadow map, the thesis's) or "
         "ray (a ray to each light through the BVH: exact)",
         toChoices(kShadowChoices)},
        {"edge_samples",
         Lights,
         kUser,
         Int,
         0,
         0,
         256,
         "",
         "rays averaged over each pixel at silhouettes, creases and shadow edges (anti-aliased "
         "direct light); 0 = off, the pixel's centre alone",
         {}},
        {"area_samples",
         Lights,
         kAdvanced,
         Int,
         8,
         1,
         256,
         "",
         "points sampled on the emitting surfaces per pixel for their direct light, each with a "
         "shadow ray (soft shadows; scenes without emitters ignore it)",
         {}},
        {"shadow_map_size",
         Lights,
         kAdvanced,
         Int,
         1024,
         16,
         8192,
         "px",
         "resolution of every light view (G-buffer, shadow map); derived: 1024 with shadows map, "
         "with ray 2 sqrt(photons) in 256..1024",
         {},
         kDerived},
        {"shadow_bias",
         Lights,
         kAdvanced,
         Float,
         1.0,
         0,
         100,
         "texels",
         "shadows map: depth margin and normal offset at grazing light, in light-view texels at "
         "the receiver's depth",
         {}},
        {"specular_depth",
         Lights,
         kAdvanced,
         Int,
         3,
         0,
         6, // each level doubles the rays a pixel may trace (a reflected and a refracted one)
         "",
         "levels of mirror and glass rays traced from what the camera sees, each hit shaded; at "
         "most bounces; 0 = off (glass black)",
         {}},
        // Photons.
        {"photons",
         Photons,
         kUser,
         Int,
         50000,
         0,
         16777216,
         "",
         "photon budget of the frame, shared among the lights (photon_share, else by power)",
         {}},
        {"bounces",
         Photons,
         kUser,
         Int,
         3,
         0,
         64, // the reference's default: --bounces reaches it in both modes
         "",
         "indirect light that reflected 1..bounces times is kept (0: direct light only); the "
         "reference's path length too",
         {}},
        {"first_bounce", Photons, kAdvanced, Enum, 0, 0, 1, "",
         "roulette (the thesis's: absorbed photons end) or weighted (every photon bounces, its "
         "power times the albedo)",
         toChoices(kFirstBounceChoices)},
        {"importance",
         Photons,
         kAdvanced,
         Float,
         0.75,
         0,
         1,
         "",
         "share of each light view's photons aimed at what the viewer sees; the rest follow the "
         "light's power (0: the thesis's uniform grid)",
         {}},
        {"importance_samples",
         Photons,
         kAdvanced,
         Int,
         8192,
         0,
         1048576,
         "",
         "viewer pixels that build the importance maps on a view's first frame (1 / "
         "importance_frames of them on each later one)",
         {}},
        {"importance_frames",
         Photons,
         kAdvanced,
         Int,
         4,
         1,
         64,
         "frames",
         "frames the importance maps average (exponentially); they start anew when settings, "
         "size, scene or emitting views change",
         {}},
        {"rng", Photons, kAdvanced, Enum, 0, 0, 2, "",
         "random numbers from frame to frame: fixed (per emission cell), per_frame (the thesis's "
         "prototype) or object_space (thesis 7.2)",
         toChoices(kRngModeChoices)},
        {"rng_generator", Photons, kAdvanced, Enum, 2, 0, 2, "",
         "pcg (a stateless hash), lcg (linear congruential) or sobol (scrambled Sobol first "
         "bounce over the grid in Z order; later ones pcg)",
         toChoices(kRngGeneratorChoices)},
        // Splat and filter.
        {"radius_mode", Splat, kUser, Enum, 2, 0, 2, "",
         "splat radius from travel distance (travel, the thesis's), path density (McGuire and "
         "Luebke) or stored photons' density (density)",
         toChoices(kRadiusModeChoices)},
        {"radius_scale",
         Splat,
         kUser,
         Float,
         1,
         1e-3,
         1e3,
         "",
         "multiplies every splat radius (derived or set)",
         {}},
        {"splat_resolution", Splat, kUser, Enum, 0, 0, 3, "",
         "splat buffer against the image, upsampled on the G-buffer; auto: 1/2 from 256 px on, "
         "else 1",
         toChoices(kSplatResolutionChoices)},
        {"denoise",
         Splat,
         kUser,
         Int,
         0,
         0,
         8,
         "",
         "edge-aware a-trous iterations on the indirect light (0 = off); derived: log2(min(w, h) "
         "/ 32) of the splat buffer, at most 3",
         {},
         kDerived},
        {"splat_neighbours",
         Splat,
         kAdvanced,
         Int,
         0,
         1,
         4096,
         "",
         "radius_mode density: photons one disc holds in a frame; derived: 0.45 sqrt(photons), 16 "
         "to 256",
         {},
         kDerived},
        {"splat_merge",
         Splat,
         kAdvanced,
         Float,
         0,
         0,
         1,
         "",
         "radius_mode density: photons in one cell of side splat_merge x the radius are drawn as "
         "one disc; 0 = each its own",
         {}},
        {"radius_min",
         Splat,
         kAdvanced,
         Float,
         0,
         1e-6,
         1e6,
         "m",
         "travel: the radius at dist_min; path_density: the smallest; density: a floor when set; "
         "derived from the area in view",
         {},
         kDerived},
        {"radius_max",
         Splat,
         kAdvanced,
         Float,
         0,
         1e-6,
         1e6,
         "m",
         "travel: the radius at dist_max; path_density: an unfocused path's; density: the "
         "largest; derived from the area in view",
         {},
         kDerived},
        {"dist_min",
         Splat,
         kAdvanced,
         Float,
         0,
         0,
         1e9,
         "m",
         "radius_mode travel: travel distance where the radius starts to grow; derived: 0",
         {},
         kDerived},
        {"dist_max",
         Splat,
         kAdvanced,
         Float,
         0,
         1e-6,
         1e9,
         "m",
         "radius_mode travel: travel distance where the radius reaches radius_max; derived: the "
         "scene's diagonal",
         {},
         kDerived},
        {"squash",
         Splat,
         kAdvanced,
         Float,
         0.1,
         1e-3,
         1,
         "",
         "splat ellipsoid thickness along the surface normal, as a fraction of its radius",
         {}},
        {"splat_mode", Splat, kAdvanced, Enum, 0, 0, 1, "",
         "raster (instanced splats, the thesis's) or gather (photons binned into 8x8-pixel tiles "
         "that each pixel sums)",
         toChoices(kSplatModeChoices)},
        {"splat_shape", Splat, kAdvanced, Enum, 0, 0, 1, "",
         "disc (a square round the disc in its surface plane) or box (the thesis's cube squashed "
         "along the normal)",
         toChoices(kSplatShapeChoices)},
        {"splat_clip", Splat, kAdvanced, Enum, 0, 0, 2, "",
         "discs cut where other surfaces meet their plane (no leak through thin walls); auto: on "
         "with radius_mode density",
         toChoices(kSplatClipChoices)},
        {"surface_ends", Splat, kAdvanced, Enum, 0, 0, 2, "",
         "without clip lines: power over the share of its disc a surface holds (G-buffer "
         "lookups); auto: on with radius_mode density",
         toChoices(kSurfaceEndsChoices)},
        {"widen_strong", Splat, kAdvanced, Enum, 0, 0, 1, "",
         "travel and path_density: a photon stronger than its light's mean is drawn sqrt(power / "
         "mean) wider, at most 2x",
         toChoices(kWidenStrongChoices)},
        // Time and accumulation.
        {"accumulate",
         Time,
         kUser,
         Int,
         0,
         0,
         65536,
         "frames",
         "frames a still view averages (new photons each); a moving view reprojects the indirect "
         "light's history; 0 = off",
         {}},
        {"frame_ms_target",
         Time,
         kUser,
         Float,
         0,
         0,
         1e6,
         "ms",
         "frame time to hold: the photon budget follows the photon passes' measured times "
         "(1,000 photons at least); 0 = off",
         {}},
        // Post-processing (linear HDR, between compose and tone map): each off by default, and
        // with all three off no post pass runs.
        {"motion_blur_shutter",
         Post,
         kUser,
         Float,
         0,
         0,
         1,
         "frames",
         "motion blur: shutter time as a fraction of a frame; light spread along each pixel's "
         "screen motion; 0 = off",
         {}},
        {"dof_aperture_m",
         Post,
         kUser,
         Float,
         0,
         0,
         10,
         "m",
         "depth blur: thin-lens diameter; light spread over each pixel's circle of confusion; 0 = "
         "off (a pinhole)",
         {}},
        {"dof_focus_m",
         Post,
         kUser,
         Float,
         0,
         1e-3,
         1e6,
         "m",
         "depth blur: distance in focus along the view axis; derived: the depth at the image "
         "centre, each frame",
         {},
         kDerived},
        {"bloom_intensity",
         Post,
         kUser,
         Float,
         0,
         0,
         1,
         "",
         "bloom: share of the light above bloom_threshold spread by a Gaussian (energy kept); 0 = "
         "off",
         {}},
        {"bloom_threshold",
         Post,
         kAdvanced,
         Float,
         1,
         0,
         1e9,
         "W/(m^2 sr)",
         "bloom: luminance (0.3 R + 0.6 G + 0.1 B, before exposure) above which light blooms",
         {}},
        {"bloom_radius_px",
         Post,
         kAdvanced,
         Float,
         16,
         1,
         64,
         "px",
         "bloom: reach of the Gaussian, 3 standard deviations",
         {}},
        // Tone map.
        {"tonemap", ToneMap, kUser, Enum, 0, 0, 2, "",
         "operator after the 2^exposure scale: thesis (luminance clamped, hue kept), filmic (ACES "
         "fit) or linear (per channel)",
         toChoices(kToneMapChoices)},
        {"exposure",
         ToneMap,
         kUser,
         Float,
         0,
         -30,
         30,
         "stops",
         "scale before tone mapping, 2^exposure",
         {}},
        {"luminance_max",
         ToneMap,
         kUser,
         Float,
         0,
         1e-6,
         1e9,
         "W/(m^2 sr)",
         "luminance mapped to white (filmic: to 97%); derived: the image's 99th percentile",
         {},
         kDerived},
        {"eye_adaptation_s",
         ToneMap,
         kAdvanced,
         Float,
         0,
         0,
         60,
         "s",
         "time constant with which a derived luminance_max follows the image (log luminance); 0 "
         "= each frame its own",
         {}},
        {"gamma",
         ToneMap,
         kAdvanced,
         Float,
         2.2,
         0.1,
         10,
         "",
         "display gamma applied after tone mapping",
         {}},
        // Debug.
        {"reference_method", Debug, kUser, Enum, 0, 0, 1, "",
         "estimator of --mode reference: path (camera paths, light sampled) or light (light "
         "paths to the camera: caustics converge)",
         toChoices(kReferenceMethodChoices)},
        {"splat_passes",
         Debug,
         kAdvanced,
         Int,
         1,
         1,
         64,
         "",
         "draw calls the splats are split into",
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

namespace {

// The default and the range as a table shows them: an enum's default and choices by name, a
// derived default as "derived".
struct TableCells {
    std::string defaultText;
    std::string range;
};

TableCells formatCells(const SettingDesc& d) {
    TableCells cells;
    if (d.type == SettingType::Enum) {
        cells.defaultText = strCat("`", d.choices.at(static_cast<size_t>(d.defaultValue)), "`");
        for (std::string_view c : d.choices)
            cells.range += (cells.range.empty() ? "" : ", ") + strCat("`", c, "`");
    } else {
        cells.defaultText = d.derived ? "derived" : formatNumber(d.defaultValue);
        cells.range = strCat(formatNumber(d.minValue), " to ", formatNumber(d.maxValue));
    }
    return cells;
}

std::string_view getLevelName(SettingLevel level) {
    return level == SettingLevel::User ? "user" : "advanced";
}

} // namespace

std::string_view getGroupName(SettingGroup group) {
    return kSettingGroupNames.at(static_cast<size_t>(group));
}

std::string formatUserSettingsMarkdown() {
    std::string out = "| group | name | default | range | unit | meaning |\n";
    out += "|---|---|---|---|---|---|\n";
    for (size_t g = 0; g < kSettingGroupNames.size(); ++g) {
        bool first = true; // the group's name on its first row only
        for (const SettingDesc& d : table()) {
            if (static_cast<size_t>(d.group) != g || d.level != SettingLevel::User) continue;
            const TableCells cells = formatCells(d);
            out +=
                strCat("| ", first ? kSettingGroupNames[g] : "", " | `", d.name, "` | ",
                       cells.defaultText, " | ", cells.range, " | ", d.unit, " | ", d.help, " |\n");
            first = false;
        }
    }
    return out;
}

std::string formatAllSettingsMarkdown() {
    std::string out;
    for (size_t g = 0; g < kSettingGroupNames.size(); ++g) {
        out += strCat(g == 0 ? "" : "\n", "### ", kSettingGroupNames[g], "\n\n");
        out += "| name | level | type | default | range | unit | meaning |\n";
        out += "|---|---|---|---|---|---|---|\n";
        for (const SettingDesc& d : table()) {
            if (static_cast<size_t>(d.group) != g) continue;
            const TableCells cells = formatCells(d);
            out +=
                strCat("| `", d.name, "` | ", getLevelName(d.level), " | ", describeType(d), " | ",
                       cells.defaultText, " | ", cells.range, " | ", d.unit, " | ", d.help, " |\n");
        }
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
