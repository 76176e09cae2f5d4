// The choices of the enum settings, in the order of their constants in shaders/shared/: the
// settings table lists them (settings.cpp), and frame_settings.cpp checks each against the
// constant the shaders compare with, at compile time.
#pragma once

#include <array>
#include <string_view>

namespace ispm {

inline constexpr std::array<std::string_view, 3> kToneMapChoices = {"thesis", "filmic", "linear"};
inline constexpr std::array<std::string_view, 3> kRngGeneratorChoices = {"pcg", "lcg", "sobol"};
inline constexpr std::array<std::string_view, 3> kRngModeChoices = {"fixed", "per_frame",
                                                                    "object_space"};
inline constexpr std::array<std::string_view, 3> kRadiusModeChoices = {"travel", "path_density",
                                                                       "density"};
inline constexpr std::array<std::string_view, 2> kReferenceMethodChoices = {"path", "light"};
inline constexpr std::array<std::string_view, 2> kSplatShapeChoices = {"disc", "box"};
inline constexpr std::array<std::string_view, 2> kSplatModeChoices = {"raster", "gather"};
inline constexpr std::array<std::string_view, 2> kShadowChoices = {"map", "ray"};
inline constexpr std::array<std::string_view, 4> kSplatResolutionChoices = {"auto", "1", "1/2",
                                                                            "1/4"};
inline constexpr std::array<std::string_view, 3> kSplatClipChoices = {"auto", "on", "off"};
inline constexpr std::array<std::string_view, 3> kSurfaceEndsChoices = {"auto", "on", "off"};
inline constexpr std::array<std::string_view, 2> kWidenStrongChoices = {"off", "on"};
inline constexpr std::array<std::string_view, 2> kFirstBounceChoices = {"roulette", "weighted"};

} // namespace ispm
