// Pixel-wise metrics (RMSE, relMSE, mean ratio) and the combined report; SSIM, which needs a
// windowed pass, lives in ssim.cpp. Sums are kept in double: a 1-megapixel image of small
// radiance values would lose digits in float.
#include "image/metrics.h"

#include "core/strings.h"
#include "scene/input_error.h"

#include <cmath>
#include <limits>

namespace ispm {
namespace {

constexpr double kChannelCount = 3.0; // RGB channels averaged over

bool isIncluded(const PixelMask* mask, size_t i) {
    return mask == nullptr || (*mask)[i] != 0;
}

// Sums f(test pixel, reference pixel) over included pixels.
template <typename Accumulate>
void sumIncluded(const Image& test, const Image& reference, const PixelMask* mask,
                 Accumulate&& accumulate) {
    for (size_t i = 0; i < test.getPixelCount(); ++i) {
        if (isIncluded(mask, i)) {
            accumulate(glm::dvec3(test.pixels[i]), glm::dvec3(reference.pixels[i]));
        }
    }
}

double computeRatio(double testSum, double referenceSum) {
    if (referenceSum != 0.0) {
        return testSum / referenceSum;
    }
    return testSum == 0.0 ? 1.0 : std::numeric_limits<double>::infinity();
}

} // namespace

size_t countIncludedPixels(const Image& test, const Image& reference, const PixelMask* mask) {
    requireSameSize(test, reference);
    requireMaskSize(test, mask);
    size_t count = 0;
    for (size_t i = 0; i < test.getPixelCount(); ++i) {
        count += isIncluded(mask, i) ? 1 : 0;
    }
    if (count == 0) {
        throw InputError(strCat("expected at least one pixel to compare, the ", test.width, "x",
                                test.height, mask ? " mask includes none" : " images are empty"));
    }
    return count;
}

double computeRmse(const Image& test, const Image& reference, const PixelMask* mask) {
    const size_t count = countIncludedPixels(test, reference, mask);
    double sum = 0.0;
    sumIncluded(test, reference, mask, [&sum](const glm::dvec3& x, const glm::dvec3& r) {
        const glm::dvec3 d = x - r;
        sum += d.x * d.x + d.y * d.y + d.z * d.z;
    });
    return std::sqrt(sum / (kChannelCount * static_cast<double>(count)));
}

double computeRelMse(const Image& test, const Image& reference, const PixelMask* mask,
                     double epsilon) {
    const size_t count = countIncludedPixels(test, reference, mask);
    double sum = 0.0;
    sumIncluded(test, reference, mask, [&sum, epsilon](const glm::dvec3& x, const glm::dvec3& r) {
        const glm::dvec3 d = x - r;
        const glm::dvec3 relative = d * d / (r * r + epsilon);
        sum += relative.x + relative.y + relative.z;
    });
    return sum / (kChannelCount * static_cast<double>(count));
}

glm::dvec3 computeMeanRatio(const Image& test, const Image& reference, const PixelMask* mask) {
    countIncludedPixels(test, reference, mask);
    glm::dvec3 testSum(0.0);
    glm::dvec3 referenceSum(0.0);
    sumIncluded(test, reference, mask, [&](const glm::dvec3& x, const glm::dvec3& r) {
        testSum += x;
        referenceSum += r;
    });
    return {computeRatio(testSum.x, referenceSum.x), computeRatio(testSum.y, referenceSum.y),
            computeRatio(testSum.z, referenceSum.z)};
}

ImageMetrics computeMetrics(const Image& test, const Image& reference, const PixelMask* mask) {
    ImageMetrics metrics;
    metrics.pixelCount = countIncludedPixels(test, reference, mask);
    metrics.rmse = computeRmse(test, reference, mask);
    metrics.relMse = computeRelMse(test, reference, mask);
    metrics.ssim = computeSsim(test, reference, mask);
    metrics.meanRatio = computeMeanRatio(test, reference, mask);
    return metrics;
}

} // namespace ispm
