// The scene's environment: radiance from every direction no surface blocks (docs/design.md
// "Environment"), a constant or the analytic sky tied to the sun, in the layout the shaders read
// (shared/environment_data.h).
#pragma once

#include <glm/glm.hpp>

#include <shared/environment_data.h>

namespace ispm {

enum class EnvironmentType { None, Constant, Sky };

struct Environment {
    EnvironmentType type = EnvironmentType::None;
    glm::vec3 radiance{0.0f};                  // constant: W/(m^2 sr)
    float turbidity = 3.0f;                    // sky: 2 (clear) to 10 (hazy)
    float scale = 1.0f;                        // sky: multiplies its radiance
    glm::vec3 sunDirection{0.0f, -1.0f, 0.0f}; // sky: the direction sunlight travels (unit)
    bool isSet() const { return type != EnvironmentType::None; }
};

// Daylight's luminous efficacy (lm/W) turning the sky model's luminance (cd/m^2) into radiance
// W/(m^2 sr): about that of diffuse skylight.
inline constexpr double kSkyLuminousEfficacy = 120.0;

// The shaders' block: for the sky, Preetham et al.'s zenith values and Perez coefficients for
// the turbidity and the sun's zenith angle.
gpu::GpuEnvironment makeGpuEnvironment(const Environment& environment);

// Radiance arriving from unit direction `toward` (as the shaders evaluate it).
glm::vec3 evaluateEnvironment(const Environment& environment, const glm::vec3& toward);

// The mean over the directions photons come from (the sphere for a constant, the upper
// hemisphere for the sky) of the radiance's Rec. 709 luminance, and their solid angle (sr).
struct EnvironmentMean {
    double luminance = 0.0;
    double solidAngleSr = 0.0;
};
EnvironmentMean computeEnvironmentMean(const Environment& environment);

} // namespace ispm
