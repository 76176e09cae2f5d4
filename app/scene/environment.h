// The scene's environment: radiance from every direction no surface blocks (docs/design.md
// "Environment"), a constant, the analytic sky tied to the sun or an equirectangular image, in the
// layout the shaders read (shared/environment_data.h).
#pragma once

#include "image/image.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

#include <shared/environment_data.h>

namespace ispm {

enum class EnvironmentType { None, Constant, Sky, Image };

// An equirectangular image and its sampling tables (the texture of kUnitEnvironmentImage):
// piecewise constant per texel, sampled by luminance x sin(theta) (pbrt's 2D distribution:
// a row by the marginal CDF, then a texel by the row's conditional CDF).
struct EnvironmentImage {
    int width = 0;                     // texels, twice the height
    int height = 0;                    // top row the zenith
    std::vector<glm::vec3> radiance;   // W/(m^2 sr), scale applied, top row first
    std::vector<float> conditionalCdf; // per row, at each texel's end (the row's last is 1)
    std::vector<float> marginalCdf;    // at each row's end (the last is 1)
    double normaliser = 0.0;           // 1 / the mean texel weight (0: the image is black)
    double luminanceIntegral = 0.0;    // the integral of luminance over the sphere, W/m^2
};

// The tables of `image` (non-negative and finite, 2:1) with its radiance x scale.
EnvironmentImage buildEnvironmentImage(const Image& image, float scale);

// The texture's texels (shared/environment_data.h kUnitEnvironmentImage), row 0 first.
std::vector<glm::vec4> packEnvironmentTexels(const EnvironmentImage& image);

struct Environment {
    EnvironmentType type = EnvironmentType::None;
    glm::vec3 radiance{0.0f};                  // constant: W/(m^2 sr)
    float turbidity = 3.0f;                    // sky: 2 (clear) to 10 (hazy)
    float scale = 1.0f;                        // sky, image: multiplies its radiance
    glm::vec3 sunDirection{0.0f, -1.0f, 0.0f}; // sky: the direction sunlight travels (unit)
    float rotationDeg = 0.0f;                  // image: about +y (right-handed: +x turns toward -z)
    std::shared_ptr<const EnvironmentImage> image; // image: the texels, scale applied
    bool isSet() const { return type != EnvironmentType::None; }
};

// An image environment from an equirectangular image (scale applied once here).
Environment makeImageEnvironment(const Image& image, float scale, float rotationDeg);

// Daylight's luminous efficacy (lm/W) turning the sky model's luminance (cd/m^2) into radiance
// W/(m^2 sr): about that of diffuse skylight.
inline constexpr double kSkyLuminousEfficacy = 120.0;

// The shaders' block: for the sky, Preetham et al.'s zenith values and Perez coefficients for
// the turbidity and the sun's zenith angle.
gpu::GpuEnvironment makeGpuEnvironment(const Environment& environment);

// Radiance arriving from unit direction `toward` (as the shaders evaluate it).
glm::vec3 evaluateEnvironment(const Environment& environment, const glm::vec3& toward);

// A direction drawn from an image environment's pdf (docs/design.md "Environment"), as
// lib/environment.glsl's sampleEnvironmentImage draws it: the radiance from there and the
// solid-angle pdf (0: nothing drawn, a black image).
struct EnvironmentSample {
    glm::vec3 toward{0.0f};
    glm::vec3 radiance{0.0f};
    float pdf = 0.0f;
};
EnvironmentSample sampleEnvironmentImage(const Environment& environment, glm::vec2 u);
// The solid-angle pdf with which sampleEnvironmentImage draws unit direction `toward`.
float computeEnvironmentImagePdf(const Environment& environment, const glm::vec3& toward);

// The mean over the directions photons come from (the sphere for a constant or an image, the
// upper hemisphere for the sky) of the radiance's Rec. 709 luminance, and their solid angle (sr).
struct EnvironmentMean {
    double luminance = 0.0;
    double solidAngleSr = 0.0;
};
EnvironmentMean computeEnvironmentMean(const Environment& environment);

} // namespace ispm
