// Tone-map statistics written on the GPU (a log-luminance histogram and the white point derived
// from it), so deriving luminance_max needs no CPU read-back.
#ifndef ISPM_TONEMAP_DATA_H
#define ISPM_TONEMAP_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

ISPM_CONST uint kLuminanceBins = 256u;
ISPM_CONST float kLog2LuminanceMin = -24.0f; // below: treated as black, not counted
ISPM_CONST float kLog2LuminanceMax = 40.0f;
ISPM_CONST float kWhitePercentile = 0.99f; // derived luminance_max: 99% of lit pixels are below
ISPM_CONST uint kExposureGroupSize = 16u;
// Each histogram invocation counts a square of this many pixels a side: a workgroup's shared
// histogram and barriers serve 16x as many pixels (on llvmpipe the pass took 10 of the thesis
// preset's 17 ms tone map with one pixel an invocation).
ISPM_CONST uint kExposurePixelsPerSide = 4u;

// Each frame clears the histogram and counts; luminanceMax stays, so the white point can adapt
// from the last frame's (eye_adaptation_s).
struct ExposureData {
    uint histogram[kLuminanceBins];
    uvec4 counts;      // x = pixels counted
    vec4 luminanceMax; // x = white point the tone map uses (adapted), y = this frame's derived
                       // one, W/(m^2 sr); x = 0 before the first frame
};
ISPM_STATIC_ASSERT_SIZE(ExposureData, 1056);

ISPM_NAMESPACE_END

#endif
