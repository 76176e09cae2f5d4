// The radii of the travel modes (radius_mode travel and path_density): where the settings leave
// them out, derived from the scene's size and the photon count. Both the splat pass (its warning
// on oversized discs) and the density pass (the travel stages' parameters) use them.
#pragma once

#include "settings/frame_settings.h"

namespace ispm {

struct SplatRadii {
    float radiusMinM = 0.0f;
    float radiusMaxM = 0.0f;
    float distMinM = 0.0f;
    float distMaxM = 0.0f;
};

// Settings where given, else derived: a base radius r0 such that `photons` discs of radius r0
// cover the area in view (GpuScene::getSurfaceArea) kSplatOverlap times; radius_min = r0 / 2 at
// dist_min = 0, radius_max = 2 r0 at dist_max = the scene's diagonal. radius_scale multiplies both
// radii. `surfaceAreaM2` and `diagonalM` describe the scene (GpuScene keeps both up to date).
SplatRadii computeSplatRadii(double surfaceAreaM2, float diagonalM, const FrameSettings& settings,
                             float radiusScale);

} // namespace ispm
