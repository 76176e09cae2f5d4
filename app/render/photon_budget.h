// How the photon budget is shared: each light gets `photon_share` of it when the scene says so,
// the remainder is split by the power each light sends into its camera's view, and each light
// view gets a regular grid of about its part (one vertex per photon).
#pragma once

#include "render/light_cameras.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace ispm {

struct EmissionGrid {
    uint32_t viewIndex = 0; // light camera / light G-buffer layer
    uint32_t width = 0;     // photons across
    uint32_t height = 0;    // photons down
    uint32_t firstPhoton = 0;
    uint32_t getCount() const { return width * height; }
};

// Luminance-weighted power (W) a light sends into what its cameras see.
double computeLightViewPower(const Light& light, const std::vector<LightCamera>& cameras,
                             uint32_t lightIndex, int resolution);

// Fractions of the budget per light, summing to 1 (or all 0 without lights or power).
std::vector<double> computeLightShares(const Scene& scene, const std::vector<LightCamera>& cameras,
                                       int resolution);

std::vector<EmissionGrid> computeEmissionGrids(const Scene& scene,
                                               const std::vector<LightCamera>& cameras,
                                               int resolution, uint32_t photons);

uint32_t countPhotons(const std::vector<EmissionGrid>& grids);

} // namespace ispm
