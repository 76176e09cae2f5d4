// What an image test needs beyond the metrics: a pass/fail summary against a golden with two
// thresholds (mean error, fraction of failing pixels) and the diff images written on failure.
#pragma once

#include "image/image.h"

namespace ispm {

struct ImageDiff {
    double meanAbsError = 0.0;    // mean over all pixels and channels of |test - reference|
    double failingFraction = 0.0; // pixels with any channel off by more than the tolerance
};

// A NaN in either image counts as a failing pixel. Throws InputError when the sizes differ.
ImageDiff computeImageDiff(const Image& test, const Image& reference, float pixelTolerance);

// |test - reference| per channel. Throws InputError when the sizes differ.
Image computeErrorImage(const Image& test, const Image& reference);

// Maps the mean of each pixel's channels, divided by `maxValue`, through the viridis colour ramp
// (0 dark purple, 1 yellow). The result is display-encoded: write it as PNG without tone mapping.
Image computeFalseColour(const Image& image, float maxValue);

} // namespace ispm
