// The travel modes' radii from the settings and the scene (splat_radii.h).
#include "render/splat_radii.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// How many discs cover a point on average with the derived base radius: enough overlap that
// one photon's noise is averaged with its neighbours', few enough to keep detail.
constexpr double kSplatOverlap = 32.0;
constexpr float kMinRadiusFactor = 0.5f;
constexpr float kMaxRadiusFactor = 2.0f;

} // namespace

SplatRadii computeSplatRadii(double surfaceAreaM2, float diagonalM, const FrameSettings& settings,
                             float radiusScale) {
    const double photons = std::max(1, settings.photons);
    const auto r0 = float(std::sqrt(kSplatOverlap * surfaceAreaM2 / (glm::pi<double>() * photons)));
    SplatRadii r;
    r.radiusMinM = settings.radiusMinM.value_or(kMinRadiusFactor * r0) * radiusScale;
    r.radiusMaxM = settings.radiusMaxM.value_or(kMaxRadiusFactor * r0) * radiusScale;
    r.distMinM = settings.distMinM.value_or(0.0f);
    r.distMaxM = settings.distMaxM.value_or(diagonalM);
    return r;
}

} // namespace ispm
