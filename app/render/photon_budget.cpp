// Photon budget arithmetic (CPU, once per scene or settings change).
#include "render/photon_budget.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

double computeLuminance(const glm::vec3& c) {
    // Rec. 709 weights: shares follow what the eye sees of each light.
    return 0.2126 * double(c.x) + 0.7152 * double(c.y) + 0.0722 * double(c.z);
}

// Integral of S(theta) sin(theta) over [0, outer], by the midpoint rule.
double integrateSpotFalloff(float innerDeg, float outerDeg) {
    constexpr int kSteps = 512; // smooth integrand: far below a photon's noise
    const double outer = glm::radians(double(outerDeg));
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * outer / kSteps;
        sum += double(computeSpotFalloff(float(std::cos(theta)), innerDeg, outerDeg)) *
               std::sin(theta);
    }
    return sum * outer / kSteps;
}

} // namespace

double computeLightViewPower(const Light& light, const std::vector<LightCamera>& cameras,
                             uint32_t lightIndex, int resolution) {
    const double twoPi = glm::two_pi<double>();
    switch (light.type) {
    case LightType::Point:
        return 2.0 * twoPi * computeLuminance(light.intensity);
    case LightType::Spot:
        return twoPi * integrateSpotFalloff(light.innerDeg, light.outerDeg) *
               computeLuminance(light.intensity);
    case LightType::Sun:
        for (const LightCamera& cam : cameras) {
            if (cam.lightIndex == lightIndex) {
                const double width = double(cam.texelSizeM) * resolution;
                return width * width * computeLuminance(light.irradiance);
            }
        }
        return 0.0;
    }
    return 0.0;
}

std::vector<double> computeLightShares(const Scene& scene, const std::vector<LightCamera>& cameras,
                                       int resolution, const Emitters& emitters,
                                       double environmentPowerW) {
    const size_t lights = scene.lights.size();
    const size_t groups = emitters.groups.size();
    const size_t n = lights + groups + (environmentPowerW > 0.0 ? 1 : 0);
    std::vector<double> shares(n, 0.0);
    std::vector<bool> isExplicit(n, false);
    double explicitSum = 0.0;
    double derivedPower = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const float share = i < lights            ? scene.lights[i].photonShare
                            : i < lights + groups ? emitters.groups[i - lights].photonShare
                                                  : -1.0f;
        if (share >= 0.0f) {
            shares[i] = share;
            isExplicit[i] = true;
            explicitSum += double(share);
        } else {
            shares[i] = i < lights ? computeLightViewPower(scene.lights[i], cameras, uint32_t(i),
                                                           resolution)
                        : i < lights + groups ? emitters.groups[i - lights].luminancePowerW
                                              : environmentPowerW;
            derivedPower += shares[i];
        }
    }
    // Explicit shares are fractions of the budget (scaled down if they add up to more than 1);
    // lights without one split what is left in proportion to their power.
    const double explicitScale = explicitSum > 1.0 ? 1.0 / explicitSum : 1.0;
    const double remainder = std::max(0.0, 1.0 - explicitSum * explicitScale);
    for (size_t i = 0; i < n; ++i) {
        if (isExplicit[i]) {
            shares[i] *= explicitScale;
        } else {
            shares[i] = derivedPower > 0.0 ? remainder * shares[i] / derivedPower : 0.0;
        }
    }
    return shares;
}

std::vector<EmissionGrid> computeEmissionGrids(const Scene& scene,
                                               const std::vector<LightCamera>& cameras,
                                               int resolution, uint32_t photons,
                                               const Emitters& emitters, double environmentPowerW) {
    const std::vector<double> shares =
        computeLightShares(scene, cameras, resolution, emitters, environmentPowerW);
    std::vector<uint32_t> viewsPerLight(scene.lights.size(), 0);
    for (const LightCamera& cam : cameras)
        if (!cam.isShadowOnly) ++viewsPerLight[cam.lightIndex];
    std::vector<EmissionGrid> grids;
    uint32_t first = 0;
    for (uint32_t v = 0; v < cameras.size(); ++v) {
        if (cameras[v].isShadowOnly) continue; // a shadow map, no photons
        const uint32_t light = cameras[v].lightIndex;
        const double perView = double(photons) * shares[light] / viewsPerLight[light];
        if (perView < 0.5) continue;
        // A square grid of about perView photons: cells of equal size in the image.
        EmissionGrid g;
        g.viewIndex = v;
        g.width = std::max(1u, uint32_t(std::lround(std::sqrt(perView))));
        g.height = std::max(1u, uint32_t(std::lround(perView / g.width)));
        g.firstPhoton = first;
        first += g.getCount();
        grids.push_back(g);
    }
    for (uint32_t group = 0; group < emitters.groups.size(); ++group) {
        const auto count =
            uint32_t(std::lround(double(photons) * shares[scene.lights.size() + group]));
        if (count == 0) continue;
        EmissionGrid g;
        g.width = count;
        g.height = 1;
        g.firstPhoton = first;
        g.emitterGroup = group;
        first += count;
        grids.push_back(g);
    }
    if (environmentPowerW > 0.0) {
        const auto count = uint32_t(std::lround(double(photons) * shares.back()));
        if (count > 0) {
            EmissionGrid g;
            g.width = count;
            g.height = 1;
            g.firstPhoton = first;
            g.emitterGroup = kEnvironmentSource;
            grids.push_back(g);
        }
    }
    return grids;
}

uint32_t countPhotons(const std::vector<EmissionGrid>& grids) {
    uint32_t total = 0;
    for (const EmissionGrid& g : grids)
        total += g.getCount();
    return total;
}

} // namespace ispm
