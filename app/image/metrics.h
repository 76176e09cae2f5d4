// Error metrics between a render and a reference, as the compare command and the image tests use
// them: RMSE, relative MSE, SSIM on tone-mapped luminance and the per-channel ratio of means
// (energy bias). All take an optional mask (non-zero = include) of the images' pixel count.
#pragma once

#include "image/image.h"

#include <glm/vec3.hpp>

#include <cstddef>

namespace ispm {

// Added to r^2 in relMSE's denominator so black reference pixels do not blow the error up; 1e-2
// is the value used in the denoising literature (Rousselle et al.), so numbers compare with it.
constexpr double kRelMseEpsilon = 1e-2;

struct ImageMetrics {
    double rmse = 0.0;
    double relMse = 0.0;
    double ssim = 1.0;
    glm::dvec3 meanRatio{1.0};
    size_t pixelCount = 0; // pixels the mask included
    // The quality figures of docs/design.md "Measuring quality", over included pixels where the
    // reference is not black; left at these values (and litPixelCount 0) when the reference is
    // black everywhere.
    size_t litPixelCount = 0;
    double energy = 1.0;   // computeEnergyRatio
    double relRmse4 = 0.0; // computeRelRmse, 4x4 blocks
    double relRmse1 = 0.0; // computeRelRmse, per pixel
};

// Side of the pixel blocks of the quality figure "rel RMSE (4x4)": errors are averaged over a
// block first, so the figure measures blotches, not per-pixel aliasing
// (docs/design.md "Measuring quality").
constexpr int kRelRmseBlock = 4;

// Every function below throws InputError when the sizes differ (naming both), when the mask has
// another pixel count, or when no pixel is included (there is nothing to compare).

// sqrt(mean over included pixels and channels of (x - r)^2).
double computeRmse(const Image& test, const Image& reference, const PixelMask* mask = nullptr);

// Mean over included pixels and channels of (x - r)^2 / (r^2 + epsilon).
double computeRelMse(const Image& test, const Image& reference, const PixelMask* mask = nullptr,
                     double epsilon = kRelMseEpsilon);

// Mean SSIM (Wang et al. 2004: 11x11 Gaussian window, sigma 1.5, C1 = (0.01 L)^2,
// C2 = (0.03 L)^2, L = 1) of tone-mapped luminance. Both images are scaled by 1 / (mean reference
// luminance) and mapped by t = Y / (1 + Y) into [0, 1): the result does not depend on exposure.
// Windows are centred on included pixels and weigh only included pixels (renormalised), so pixels
// outside the mask, or outside the image at its border, never enter the statistics.
double computeSsim(const Image& test, const Image& reference, const PixelMask* mask = nullptr);

// Per channel, sum(test) / sum(reference) over included pixels: 1 means no energy bias. A zero
// reference sum gives 1 if the test sum is zero too, else +inf.
glm::dvec3 computeMeanRatio(const Image& test, const Image& reference,
                            const PixelMask* mask = nullptr);

// Pixels compared by the quality figures: included by the mask and not black in the reference
// (some channel above 0); possibly none. The two functions below throw InputError when none is.
PixelMask selectLitPixels(const Image& reference, const PixelMask* mask);

// mean(test) / mean(reference) over the lit pixels, all channels together: the energy of
// docs/design.md "Measuring quality".
double computeEnergyRatio(const Image& test, const Image& reference,
                          const PixelMask* mask = nullptr);

// The rel RMSE of docs/design.md "Measuring quality": each channel averaged over the lit pixels
// of every blockPx x blockPx block (blocks without one are left out), then sqrt(mean over blocks
// and channels of (test - reference)^2) / mean(reference over lit pixels and channels).
// blockPx 1 = per pixel.
double computeRelRmse(const Image& test, const Image& reference, int blockPx,
                      const PixelMask* mask = nullptr);

ImageMetrics computeMetrics(const Image& test, const Image& reference,
                            const PixelMask* mask = nullptr);

// Number of included pixels; throws InputError on a size or mask mismatch or when it is zero.
size_t countIncludedPixels(const Image& test, const Image& reference, const PixelMask* mask);

} // namespace ispm
