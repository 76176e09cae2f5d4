// Golden-image comparison for the image tests and the diff images they write on failure. Unlike
// the metrics these never throw on NaN: a NaN pixel simply fails.
#include "image/image_diff.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace ispm {
namespace {

constexpr float kMaxSrgb8 = 255.0f; // the ramp below is given in 8-bit sRGB
constexpr int kChannelCount = 3;
// Viridis (matplotlib's default ramp: perceptually uniform, readable by colour-blind people)
// sampled at 0, 1/4, 1/2, 3/4 and 1, as 8-bit sRGB.
constexpr std::array<glm::vec3, 5> kViridisStops = {
    glm::vec3(68.0f, 1.0f, 84.0f), glm::vec3(59.0f, 82.0f, 139.0f),
    glm::vec3(33.0f, 145.0f, 140.0f), glm::vec3(94.0f, 201.0f, 98.0f),
    glm::vec3(253.0f, 231.0f, 37.0f)};

glm::vec3 evaluateViridis(float t) {
    constexpr float kLastStop = static_cast<float>(kViridisStops.size() - 1);
    // NaN goes to the bottom of the ramp like zero; NaN must not become an index.
    const float clamped = t > 0.0f ? std::min(t, 1.0f) : 0.0f;
    const float position = clamped * kLastStop;
    const size_t lower = std::min(static_cast<size_t>(position), kViridisStops.size() - 2);
    const float fraction = position - static_cast<float>(lower);
    return glm::mix(kViridisStops[lower], kViridisStops[lower + 1], fraction) / kMaxSrgb8;
}

} // namespace

ImageDiff computeImageDiff(const Image& test, const Image& reference, float pixelTolerance) {
    requireSameSize(test, reference);
    ImageDiff diff;
    if (test.isEmpty()) {
        return diff;
    }
    double absErrorSum = 0.0;
    size_t failingCount = 0;
    for (size_t i = 0; i < test.getPixelCount(); ++i) {
        const glm::vec3 error = glm::abs(test.pixels[i] - reference.pixels[i]);
        absErrorSum += static_cast<double>(error.r) + static_cast<double>(error.g) +
                       static_cast<double>(error.b);
        // Comparisons with NaN are false: a NaN pixel does not pass.
        const bool passes =
            error.r <= pixelTolerance && error.g <= pixelTolerance && error.b <= pixelTolerance;
        failingCount += passes ? 0 : 1;
    }
    const double pixelCount = static_cast<double>(test.getPixelCount());
    diff.meanAbsError = absErrorSum / (kChannelCount * pixelCount);
    diff.failingFraction = static_cast<double>(failingCount) / pixelCount;
    return diff;
}

Image computeErrorImage(const Image& test, const Image& reference) {
    requireSameSize(test, reference);
    Image error(test.width, test.height);
    for (size_t i = 0; i < test.getPixelCount(); ++i) {
        error.pixels[i] = glm::abs(test.pixels[i] - reference.pixels[i]);
    }
    return error;
}

Image computeFalseColour(const Image& image, float maxValue) {
    Image colours(image.width, image.height);
    for (size_t i = 0; i < image.getPixelCount(); ++i) {
        const glm::vec3& pixel = image.pixels[i];
        const float mean = (pixel.r + pixel.g + pixel.b) / static_cast<float>(kChannelCount);
        colours.pixels[i] = evaluateViridis(maxValue > 0.0f ? mean / maxValue : 0.0f);
    }
    return colours;
}

} // namespace ispm
