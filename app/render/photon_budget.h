// How the photon budget is shared: each light gets `photon_share` of it when the scene says so,
// the remainder is split by the power each light sends into its camera's view, and each light
// view gets a regular grid of about its part (one vertex per photon).
#pragma once

#include "render/light_cameras.h"
#include "scene/emitters.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace ispm {

inline constexpr uint32_t kNoEmitterGroup = 0xffffffffu;
inline constexpr uint32_t kEnvironmentSource = 0xfffffffeu; // EmissionGrid::emitterGroup

// The photons of one light view (a grid through its G-buffer), of one group of emitting
// triangles (emitterGroup: width photons in a row, traced from points on them through the BVH),
// or of the environment (emitterGroup kEnvironmentSource, the same).
struct EmissionGrid {
    uint32_t viewIndex = 0; // light camera / light G-buffer layer
    uint32_t width = 0;     // photons across
    uint32_t height = 0;    // photons down
    uint32_t firstPhoton = 0;
    uint32_t emitterGroup = kNoEmitterGroup; // Emitters::groups index
    uint32_t getCount() const { return width * height; }
    bool isEmitterGroup() const {
        return emitterGroup != kNoEmitterGroup && emitterGroup != kEnvironmentSource;
    }
    bool isEnvironment() const { return emitterGroup == kEnvironmentSource; }
};

// Luminance-weighted power (W) a light sends into what its cameras see.
double computeLightViewPower(const Light& light, const std::vector<LightCamera>& cameras,
                             uint32_t lightIndex, int resolution);

// Fractions of the budget per light, then per emitter group, summing to 1 (or all 0 without
// lights or power). An emitter group's power is what its triangles send out (its material's
// photon_share, when set, as a light's).
// The environment comes last, by the luminance of the power it sends through the disc its
// photons enter by (GpuScene::getEnvironmentPowerW).
std::vector<double> computeLightShares(const Scene& scene, const std::vector<LightCamera>& cameras,
                                       int resolution, const Emitters& emitters = {},
                                       double environmentPowerW = 0.0);

// The light views' grids, then a row of photons per emitter group, then the environment's row,
// in photon order.
std::vector<EmissionGrid> computeEmissionGrids(const Scene& scene,
                                               const std::vector<LightCamera>& cameras,
                                               int resolution, uint32_t photons,
                                               const Emitters& emitters = {},
                                               double environmentPowerW = 0.0);

uint32_t countPhotons(const std::vector<EmissionGrid>& grids);

} // namespace ispm
