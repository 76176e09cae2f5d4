// The environment's sky model (Preetham, Shirley and Smits 1999, appendix A.2).
#include "scene/environment.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// Perez coefficients A..D and E, linear in the turbidity T: A = a0 T + a1, ...
void setPerez(glm::vec4 out[2], float t, const float (&c)[5][2]) {
    out[0] = glm::vec4(c[0][0] * t + c[0][1], c[1][0] * t + c[1][1], c[2][0] * t + c[2][1],
                       c[3][0] * t + c[3][1]);
    out[1] = glm::vec4(c[4][0] * t + c[4][1], 0.0f, 0.0f, 0.0f);
}

// A zenith chromaticity: T^2 (a . th) + T (b . th) + (c . th), th = (theta^3, theta^2, theta, 1).
float computeZenithChromaticity(float t, float theta, const float (&c)[3][4]) {
    const glm::vec4 th(theta * theta * theta, theta * theta, theta, 1.0f);
    const auto row = [&](int r) {
        return glm::dot(glm::vec4(c[r][0], c[r][1], c[r][2], c[r][3]), th);
    };
    return t * t * row(0) + t * row(1) + row(2);
}

constexpr float kPerezY[5][2] = {{0.1787f, -1.4630f},
                                 {-0.3554f, 0.4275f},
                                 {-0.0227f, 5.3251f},
                                 {0.1206f, -2.5771f},
                                 {-0.0670f, 0.3703f}};
constexpr float kPerezX[5][2] = {{-0.0193f, -0.2592f},
                                 {-0.0665f, 0.0008f},
                                 {-0.0004f, 0.2125f},
                                 {-0.0641f, -0.8989f},
                                 {-0.0033f, 0.0452f}};
constexpr float kPerezChromaY[5][2] = {{-0.0167f, -0.2608f},
                                       {-0.0950f, 0.0092f},
                                       {-0.0079f, 0.2102f},
                                       {-0.0441f, -1.6537f},
                                       {-0.0109f, 0.0529f}};
constexpr float kZenithX[3][4] = {{0.00166f, -0.00375f, 0.00209f, 0.0f},
                                  {-0.02903f, 0.06377f, -0.03202f, 0.00394f},
                                  {0.11693f, -0.21196f, 0.06052f, 0.25886f}};
constexpr float kZenithY[3][4] = {{0.00275f, -0.00610f, 0.00317f, 0.0f},
                                  {-0.04214f, 0.08970f, -0.04153f, 0.00516f},
                                  {0.15346f, -0.26756f, 0.06670f, 0.26688f}};

} // namespace

gpu::GpuEnvironment makeGpuEnvironment(const Environment& environment) {
    gpu::GpuEnvironment g{};
    switch (environment.type) {
    case EnvironmentType::None:
        g.type.x = gpu::kEnvironmentNone;
        return g;
    case EnvironmentType::Constant:
        g.type.x = gpu::kEnvironmentConstant;
        g.radiance = glm::vec4(environment.radiance, 1.0f);
        return g;
    case EnvironmentType::Sky:
        break;
    case EnvironmentType::Image: {
        const EnvironmentImage& image = *environment.image;
        const float alpha = glm::radians(environment.rotationDeg);
        g.type =
            glm::uvec4(gpu::kEnvironmentImage, uint32_t(image.width), uint32_t(image.height), 0u);
        g.image = glm::vec4(std::cos(alpha), std::sin(alpha), float(image.normaliser), 0.0f);
        return g;
    }
    }
    g.type.x = gpu::kEnvironmentSky;
    g.radiance = glm::vec4(0.0f, 0.0f, 0.0f, environment.scale);
    const glm::vec3 toSun = -glm::normalize(environment.sunDirection);
    // A sun under the horizon: the model's zenith luminance stops at sunset (theta_s = 90).
    const float theta = std::acos(glm::clamp(toSun.y, 0.0f, 1.0f));
    g.toSun = glm::vec4(toSun, theta);
    const float t = environment.turbidity;
    const float chi = (4.0f / 9.0f - t / 120.0f) * (glm::pi<float>() - 2.0f * theta);
    const float zenithKcd =
        std::max((4.0453f * t - 4.9710f) * std::tan(chi) - 0.2155f * t + 2.4192f, 0.0f);
    g.zenith = glm::vec4(float(double(zenithKcd) * 1000.0 / kSkyLuminousEfficacy),
                         computeZenithChromaticity(t, theta, kZenithX),
                         computeZenithChromaticity(t, theta, kZenithY), 0.0f);
    setPerez(g.perezY, t, kPerezY);
    setPerez(g.perezX, t, kPerezX);
    setPerez(g.perezChromaY, t, kPerezChromaY);
    return g;
}

glm::vec3 evaluateEnvironment(const Environment& environment, const glm::vec3& toward) {
    if (environment.type == EnvironmentType::Image) {
        const EnvironmentImage& image = *environment.image;
        const gpu::GpuEnvironment g = makeGpuEnvironment(environment);
        const glm::vec2 uv = gpu::computeEnvironmentUv(toward, glm::vec2(g.image));
        const int x = std::min(int(uv.x * float(image.width)), image.width - 1);
        const int y = std::min(int(uv.y * float(image.height)), image.height - 1);
        return image.radiance[size_t(y) * size_t(image.width) + size_t(x)];
    }
    return gpu::evaluateEnvironment(makeGpuEnvironment(environment), toward);
}

EnvironmentMean computeEnvironmentMean(const Environment& environment) {
    EnvironmentMean mean;
    if (environment.type == EnvironmentType::None) return mean;
    const glm::vec3 rec709(0.2126f, 0.7152f, 0.0722f);
    if (environment.type == EnvironmentType::Image) {
        mean.solidAngleSr = 4.0 * glm::pi<double>();
        mean.luminance = environment.image->luminanceIntegral / mean.solidAngleSr;
        return mean;
    }
    if (environment.type == EnvironmentType::Constant) {
        mean.luminance = double(glm::dot(environment.radiance, rec709));
        mean.solidAngleSr = 4.0 * glm::pi<double>();
        return mean;
    }
    // The upper hemisphere by the midpoint rule in (cos theta, phi): a smooth function.
    const gpu::GpuEnvironment g = makeGpuEnvironment(environment);
    constexpr int kSteps = 32;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double z = (i + 0.5) / kSteps;
        const double r = std::sqrt(1.0 - z * z);
        for (int j = 0; j < 2 * kSteps; ++j) {
            const double phi = glm::two_pi<double>() * (j + 0.5) / (2 * kSteps);
            const glm::vec3 dir(float(r * std::cos(phi)), float(z), float(r * std::sin(phi)));
            sum += double(glm::dot(gpu::evaluateEnvironment(g, dir), rec709));
        }
    }
    mean.luminance = sum / (2.0 * kSteps * kSteps);
    mean.solidAngleSr = glm::two_pi<double>();
    return mean;
}

} // namespace ispm
