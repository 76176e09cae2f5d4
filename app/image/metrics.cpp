// Pixel-wise metrics (RMSE, relMSE, mean ratio) and the combined report; SSIM, which needs a
// windowed pass, lives in ssim.cpp. Sums are kept in double: a 1-megapixel image of small
// radiance values would lose digits in float.
#include "image/metrics.h"

#include "core/input_error.h"
#include "core/strings.h"

#include <algorithm>
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

PixelMask selectLitPixels(const Image& reference, const PixelMask* mask) {
    requireMaskSize(reference, mask);
    PixelMask lit(reference.getPixelCount(), 0);
    for (size_t i = 0; i < lit.size(); ++i) {
        const glm::vec3& r = reference.pixels[i];
        lit[i] = isIncluded(mask, i) && (r.x > 0.0f || r.y > 0.0f || r.z > 0.0f) ? 1 : 0;
    }
    return lit;
}

namespace {

// The lit pixels, or InputError when the reference is black wherever it is compared.
PixelMask requireLitPixels(const Image& test, const Image& reference, const PixelMask* mask) {
    requireSameSize(test, reference);
    PixelMask lit = selectLitPixels(reference, mask);
    if (std::find(lit.begin(), lit.end(), 1) == lit.end()) {
        throw InputError(strCat("expected a reference with a pixel that is not black among the ",
                                test.width, "x", test.height, " compared"));
    }
    return lit;
}

} // namespace

double computeEnergyRatio(const Image& test, const Image& reference, const PixelMask* mask) {
    const PixelMask lit = requireLitPixels(test, reference, mask);
    double testSum = 0.0;
    double referenceSum = 0.0;
    sumIncluded(test, reference, &lit, [&](const glm::dvec3& x, const glm::dvec3& r) {
        testSum += x.x + x.y + x.z;
        referenceSum += r.x + r.y + r.z;
    });
    return testSum / referenceSum;
}

double computeRelRmse(const Image& test, const Image& reference, int blockPx,
                      const PixelMask* mask) {
    const PixelMask lit = requireLitPixels(test, reference, mask);
    double squaredSum = 0.0;
    double blockCount = 0.0;
    double referenceSum = 0.0;
    double litCount = 0.0;
    for (int by = 0; by < test.height; by += blockPx) {
        for (int bx = 0; bx < test.width; bx += blockPx) {
            glm::dvec3 testMean(0.0);
            glm::dvec3 referenceMean(0.0);
            double n = 0.0;
            for (int y = by; y < std::min(by + blockPx, test.height); ++y) {
                for (int x = bx; x < std::min(bx + blockPx, test.width); ++x) {
                    const size_t i = size_t(y) * size_t(test.width) + size_t(x);
                    if (!lit[i]) continue;
                    testMean += glm::dvec3(test.pixels[i]);
                    referenceMean += glm::dvec3(reference.pixels[i]);
                    n += 1.0;
                }
            }
            if (n == 0.0) continue;
            referenceSum += referenceMean.x + referenceMean.y + referenceMean.z;
            litCount += n;
            const glm::dvec3 d = (testMean - referenceMean) / n;
            squaredSum += d.x * d.x + d.y * d.y + d.z * d.z;
            blockCount += 1.0;
        }
    }
    const double referenceMean = referenceSum / (kChannelCount * litCount);
    return std::sqrt(squaredSum / (kChannelCount * blockCount)) / referenceMean;
}

ImageMetrics computeMetrics(const Image& test, const Image& reference, const PixelMask* mask) {
    ImageMetrics metrics;
    metrics.pixelCount = countIncludedPixels(test, reference, mask);
    metrics.rmse = computeRmse(test, reference, mask);
    metrics.relMse = computeRelMse(test, reference, mask);
    metrics.ssim = computeSsim(test, reference, mask);
    metrics.meanRatio = computeMeanRatio(test, reference, mask);
    const PixelMask lit = selectLitPixels(reference, mask);
    metrics.litPixelCount = size_t(std::count(lit.begin(), lit.end(), 1));
    if (metrics.litPixelCount > 0) {
        metrics.energy = computeEnergyRatio(test, reference, &lit);
        metrics.relRmse4 = computeRelRmse(test, reference, kRelRmseBlock, &lit);
        metrics.relRmse1 = computeRelRmse(test, reference, 1, &lit);
    }
    return metrics;
}

} // namespace ispm
