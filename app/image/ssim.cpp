// Structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004) on tone-mapped luminance. The
// Gaussian-weighted window statistics come from separable blurs of mask-weighted planes divided by
// the blurred mask: the same as a window renormalised over the included, in-image pixels.
#include "image/metrics.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace ispm {
namespace {

constexpr int kWindowRadiusPx = 5;     // 11x11 window, as in Wang et al.
constexpr double kWindowSigmaPx = 1.5; // Gaussian sigma of the window, as in Wang et al.
constexpr double kDynamicRange = 1.0;  // L: tone-mapped values lie in [0, 1)
constexpr double kK1 = 0.01;           // Wang et al.'s constants for C1 = (K1 L)^2 ...
constexpr double kK2 = 0.03;           // ... and C2 = (K2 L)^2
constexpr double kC1 = (kK1 * kDynamicRange) * (kK1 * kDynamicRange);
constexpr double kC2 = (kK2 * kDynamicRange) * (kK2 * kDynamicRange);
// Rec. 709 / sRGB primaries: the renderer's linear RGB.
constexpr glm::dvec3 kLuminanceWeights{0.2126, 0.7152, 0.0722};

constexpr size_t kWindowSize = 2 * kWindowRadiusPx + 1;
using Kernel = std::array<double, kWindowSize>;

Kernel buildGaussianKernel() {
    Kernel kernel{};
    double sum = 0.0;
    for (int i = -kWindowRadiusPx; i <= kWindowRadiusPx; ++i) {
        const double weight = std::exp(-(i * i) / (2.0 * kWindowSigmaPx * kWindowSigmaPx));
        kernel[static_cast<size_t>(i + kWindowRadiusPx)] = weight;
        sum += weight;
    }
    for (double& weight : kernel) {
        weight /= sum;
    }
    return kernel;
}

// Maps scaled luminance into [0, 1). Negative values (noise in a difference, never radiance) go
// to 0; +inf goes to 1 rather than inf/inf; NaN stays NaN so that it shows in the score.
double toneMap(double luminance) {
    if (std::isinf(luminance)) {
        return luminance > 0.0 ? 1.0 : 0.0;
    }
    const double y = luminance < 0.0 ? 0.0 : luminance;
    return y / (1.0 + y);
}

// Blurs a plane with the kernel along x then y, treating everything outside the image as 0.
void blurPlane(std::vector<double>& plane, int width, int height, const Kernel& kernel) {
    std::vector<double> rows(plane.size(), 0.0);
    const auto index = [width](int x, int y) {
        return static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
    };
    const auto tap = [&kernel](int k) { return kernel[static_cast<size_t>(k + kWindowRadiusPx)]; };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int k = -kWindowRadiusPx; k <= kWindowRadiusPx; ++k) {
                if (x + k >= 0 && x + k < width) {
                    sum += tap(k) * plane[index(x + k, y)];
                }
            }
            rows[index(x, y)] = sum;
        }
    }
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int k = -kWindowRadiusPx; k <= kWindowRadiusPx; ++k) {
                if (y + k >= 0 && y + k < height) {
                    sum += tap(k) * rows[index(x, y + k)];
                }
            }
            plane[index(x, y)] = sum;
        }
    }
}

double computeLuminance(const glm::vec3& rgb) {
    return glm::dot(glm::dvec3(rgb), kLuminanceWeights);
}

} // namespace

double computeSsim(const Image& test, const Image& reference, const PixelMask* mask) {
    const size_t count = countIncludedPixels(test, reference, mask);
    const size_t pixelCount = test.getPixelCount();
    const auto isIncluded = [mask](size_t i) { return mask == nullptr || (*mask)[i] != 0; };

    // One exposure for both images, from the reference: a render that is uniformly too bright
    // still scores below 1, and doubling both images changes nothing.
    double referenceLuminanceSum = 0.0;
    for (size_t i = 0; i < pixelCount; ++i) {
        if (isIncluded(i)) {
            referenceLuminanceSum += computeLuminance(reference.pixels[i]);
        }
    }
    const double meanLuminance = referenceLuminanceSum / static_cast<double>(count);
    const bool canNormalise = std::isfinite(meanLuminance) && meanLuminance > 0.0;
    const double exposure = canNormalise ? 1.0 / meanLuminance : 1.0;

    // Mask-weighted moments: w, w x, w y, w x^2, w y^2, w x y. Excluded pixels are written as
    // zeros (not w * value) so that a NaN outside the mask cannot leak into a window.
    enum Moment { kWeight, kX, kY, kXX, kYY, kXY, kMomentCount };
    std::array<std::vector<double>, kMomentCount> moments;
    for (std::vector<double>& plane : moments) {
        plane.assign(pixelCount, 0.0);
    }
    for (size_t i = 0; i < pixelCount; ++i) {
        if (!isIncluded(i)) {
            continue;
        }
        const double x = toneMap(exposure * computeLuminance(test.pixels[i]));
        const double y = toneMap(exposure * computeLuminance(reference.pixels[i]));
        moments[kWeight][i] = 1.0;
        moments[kX][i] = x;
        moments[kY][i] = y;
        moments[kXX][i] = x * x;
        moments[kYY][i] = y * y;
        moments[kXY][i] = x * y;
    }
    const Kernel kernel = buildGaussianKernel();
    for (std::vector<double>& plane : moments) {
        blurPlane(plane, test.width, test.height, kernel);
    }

    double ssimSum = 0.0;
    for (size_t i = 0; i < pixelCount; ++i) {
        if (!isIncluded(i)) {
            continue;
        }
        // Positive: the pixel itself is included and has the window's largest weight.
        const double weight = moments[kWeight][i];
        const double muX = moments[kX][i] / weight;
        const double muY = moments[kY][i] / weight;
        const double varX = moments[kXX][i] / weight - muX * muX;
        const double varY = moments[kYY][i] / weight - muY * muY;
        const double covXY = moments[kXY][i] / weight - muX * muY;
        ssimSum += ((2.0 * muX * muY + kC1) * (2.0 * covXY + kC2)) /
                   ((muX * muX + muY * muY + kC1) * (varX + varY + kC2));
    }
    return ssimSum / static_cast<double>(count);
}

} // namespace ispm
