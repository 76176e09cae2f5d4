// Error metrics and golden-diff helpers: hand-computed RMSE and relMSE, SSIM's properties
// (identity, monotonic in noise, exposure independence), masks, mean ratio and size errors.
#include "core/input_error.h"
#include "image/image_diff.h"
#include "image/metrics.h"

#include <glm/vector_relational.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace ispm {
namespace {

constexpr double kTolerance = 1e-12;
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

// A smooth gradient with a checker pattern on top: structure for SSIM to see.
Image makePatternImage(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float checker = ((x / 4 + y / 4) % 2 == 0) ? 0.5f : 0.0f;
            const float ramp = static_cast<float>(x + y) / static_cast<float>(width + height);
            image.at(x, y) = glm::vec3(ramp + checker, 0.5f * ramp + checker, 0.25f + checker);
        }
    }
    return image;
}

Image addNoise(const Image& image, float sigma, uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> noise(0.0f, sigma);
    Image noisy = image;
    for (glm::vec3& pixel : noisy.pixels) {
        pixel += glm::vec3(noise(rng), noise(rng), noise(rng));
    }
    return noisy;
}

// The two-pixel pair whose errors are worked out by hand below.
struct KnownPair {
    Image test{2, 1};
    Image reference{2, 1};
    KnownPair() {
        reference.at(0, 0) = glm::vec3(0.0f, 0.0f, 0.0f);
        reference.at(1, 0) = glm::vec3(1.0f, 1.0f, 1.0f);
        test.at(0, 0) = glm::vec3(1.0f, 0.0f, 0.0f); // squared errors 1, 0, 0
        test.at(1, 0) = glm::vec3(1.0f, 1.0f, 3.0f); // squared errors 0, 0, 4
    }
};

TEST(MetricsTest, RmseMatchesHandComputedValue) {
    const KnownPair pair;
    EXPECT_NEAR(computeRmse(pair.test, pair.reference), std::sqrt(5.0 / 6.0), kTolerance);
}

TEST(MetricsTest, RelMseMatchesHandComputedValue) {
    const KnownPair pair;
    // 1 / (0 + eps) in the black pixel, 4 / (1 + eps) in the white one, over 6 channels.
    const double expected = (1.0 / kRelMseEpsilon + 4.0 / (1.0 + kRelMseEpsilon)) / 6.0;
    EXPECT_NEAR(computeRelMse(pair.test, pair.reference), expected, kTolerance);
    EXPECT_NEAR(computeRelMse(pair.test, pair.reference, nullptr, 1.0), (1.0 + 2.0) / 6.0,
                kTolerance);
}

TEST(MetricsTest, ComputeMetricsGathersAll) {
    const KnownPair pair;
    const ImageMetrics metrics = computeMetrics(pair.test, pair.reference);
    EXPECT_EQ(metrics.pixelCount, 2u);
    EXPECT_DOUBLE_EQ(metrics.rmse, computeRmse(pair.test, pair.reference));
    EXPECT_DOUBLE_EQ(metrics.relMse, computeRelMse(pair.test, pair.reference));
    EXPECT_DOUBLE_EQ(metrics.ssim, computeSsim(pair.test, pair.reference));
    EXPECT_EQ(metrics.meanRatio, glm::dvec3(2.0, 1.0, 3.0));
}

TEST(SsimTest, IsOneForIdenticalImages) {
    const Image image = makePatternImage(32, 24);
    EXPECT_NEAR(computeSsim(image, image), 1.0, kTolerance);
    const Image tiny(1, 1, glm::vec3(0.3f));
    EXPECT_NEAR(computeSsim(tiny, tiny), 1.0, kTolerance);
    const Image black(5, 3);
    EXPECT_NEAR(computeSsim(black, black), 1.0, kTolerance);
}

TEST(SsimTest, DecreasesWithMoreNoise) {
    const Image reference = makePatternImage(32, 24);
    double previous = 1.0;
    for (const float sigma : {0.02f, 0.1f, 0.3f}) {
        const double ssim = computeSsim(addNoise(reference, sigma, 11), reference);
        EXPECT_LT(ssim, previous) << "sigma " << sigma;
        EXPECT_GT(ssim, 0.0) << "sigma " << sigma;
        previous = ssim;
    }
}

TEST(SsimTest, IsExposureIndependentButSeesBias) {
    const Image reference = makePatternImage(16, 16);
    const Image test = addNoise(reference, 0.1f, 5);
    Image brighterTest = test;
    Image brighterReference = reference;
    for (glm::vec3& pixel : brighterTest.pixels) {
        pixel *= 8.0f;
    }
    for (glm::vec3& pixel : brighterReference.pixels) {
        pixel *= 8.0f;
    }
    EXPECT_NEAR(computeSsim(brighterTest, brighterReference), computeSsim(test, reference), 1e-9);
    // Only the test brighter: a uniform bias must cost something.
    EXPECT_LT(computeSsim(brighterTest, test), 1.0 - 1e-3);
}

TEST(MetricsTest, MaskRestrictsEveryMetric) {
    const Image reference = makePatternImage(16, 8);
    Image test = reference;
    PixelMask leftHalf(reference.getPixelCount(), 0);
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            if (x < test.width / 2) {
                leftHalf[static_cast<size_t>(y * test.width + x)] = 1;
            } else {
                test.at(x, y) = glm::vec3(kNan, 100.0f, -5.0f); // garbage outside the mask
            }
        }
    }
    const ImageMetrics masked = computeMetrics(test, reference, &leftHalf);
    EXPECT_EQ(masked.pixelCount, reference.getPixelCount() / 2);
    EXPECT_EQ(masked.rmse, 0.0);
    EXPECT_EQ(masked.relMse, 0.0);
    EXPECT_NEAR(masked.ssim, 1.0, kTolerance);
    EXPECT_EQ(masked.meanRatio, glm::dvec3(1.0));

    test.at(0, 0) += glm::vec3(1.0f); // inside the mask: now it shows
    EXPECT_GT(computeRmse(test, reference, &leftHalf), 0.0);
}

TEST(MetricsTest, MeanRatioOfDoubledImageIsTwo) {
    const Image reference = makePatternImage(9, 7);
    Image doubled = reference;
    for (glm::vec3& pixel : doubled.pixels) {
        pixel *= 2.0f;
    }
    const glm::dvec3 ratio = computeMeanRatio(doubled, reference);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(ratio[c], 2.0, kTolerance);
    }
}

TEST(MetricsTest, MeanRatioOfZeroReference) {
    const Image black(2, 2);
    Image test(2, 2);
    test.at(1, 1).g = 0.5f;
    const glm::dvec3 ratio = computeMeanRatio(test, black);
    EXPECT_EQ(ratio.r, 1.0);
    EXPECT_EQ(ratio.g, std::numeric_limits<double>::infinity());
    EXPECT_EQ(ratio.b, 1.0);
}

TEST(MetricsTest, SizeMismatchNamesBothSizes) {
    try {
        computeMetrics(Image(7, 3), Image(8, 3));
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("7x3"), std::string::npos) << message;
        EXPECT_NE(message.find("8x3"), std::string::npos) << message;
    }
    EXPECT_THROW(computeSsim(Image(2, 2), Image(2, 3)), InputError);
    EXPECT_THROW(computeImageDiff(Image(2, 2), Image(3, 2), 0.0f), InputError);
    EXPECT_THROW(computeErrorImage(Image(2, 2), Image(3, 2)), InputError);
}

TEST(MetricsTest, BadMasksThrow) {
    const Image image(3, 3);
    const PixelMask wrongSize(4, 1);
    EXPECT_THROW(computeRmse(image, image, &wrongSize), InputError);
    const PixelMask empty(9, 0);
    EXPECT_THROW(computeMetrics(image, image, &empty), InputError);
    EXPECT_THROW(computeRmse(Image(), Image()), InputError);
}

TEST(ImageDiffTest, CountsFailingPixelsAndMeanError) {
    Image reference(4, 1, glm::vec3(0.5f));
    Image test = reference;
    test.at(0, 0).r += 0.25f; // fails a 0.1 tolerance
    test.at(1, 0).b -= 0.05f; // passes it
    test.at(2, 0).g = kNan;   // a NaN always fails
    const ImageDiff diff = computeImageDiff(test, reference, 0.1f);
    EXPECT_DOUBLE_EQ(diff.failingFraction, 2.0 / 4.0);
    EXPECT_TRUE(std::isnan(diff.meanAbsError));

    test.at(2, 0).g = 0.5f;
    EXPECT_NEAR(computeImageDiff(test, reference, 0.1f).meanAbsError, (0.25 + 0.05) / 12.0, 1e-7);
    EXPECT_EQ(computeImageDiff(reference, reference, 0.0f).failingFraction, 0.0);
}

TEST(ImageDiffTest, ErrorImageIsAbsoluteDifference) {
    Image a(1, 1, glm::vec3(1.0f, 2.0f, 3.0f));
    Image b(1, 1, glm::vec3(3.0f, 2.0f, 0.5f));
    EXPECT_EQ(computeErrorImage(a, b).at(0, 0), glm::vec3(2.0f, 0.0f, 2.5f));
}

TEST(ImageDiffTest, FalseColourSpansTheRampAndSurvivesNan) {
    Image errors(4, 1);
    errors.at(1, 0) = glm::vec3(2.0f);  // max value: top of the ramp
    errors.at(2, 0) = glm::vec3(10.0f); // above max: clamped to the top
    errors.at(3, 0) = glm::vec3(kNan);
    const Image colours = computeFalseColour(errors, 2.0f);
    EXPECT_EQ(colours.at(0, 0), colours.at(3, 0));
    EXPECT_EQ(colours.at(1, 0), colours.at(2, 0));
    EXPECT_GT(colours.at(1, 0).r + colours.at(1, 0).g, colours.at(0, 0).r + colours.at(0, 0).g);
    for (const glm::vec3& colour : colours.pixels) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(colour, glm::vec3(0.0f))));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(colour, glm::vec3(1.0f))));
    }
}

TEST(QualityMetrics, EnergyAndBlockRelRmseByHand) {
    // Reference: 8x4, left half 1, right half black (left out); test: the left 4x4 block is 1.5
    // everywhere and the right half anything.
    Image reference(8, 4);
    Image test(8, 4, glm::vec3(7.0f));
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            reference.at(x, y) = glm::vec3(1.0f);
            test.at(x, y) = glm::vec3(1.5f);
        }
    }
    EXPECT_NEAR(computeEnergyRatio(test, reference), 1.5, kTolerance);
    EXPECT_NEAR(computeRelRmse(test, reference, kRelRmseBlock), 0.5, kTolerance);
    // Noise that averages out within a block counts per pixel, not per block.
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x)
            test.at(x, y) = glm::vec3((x + y) % 2 == 0 ? 1.2f : 0.8f);
    }
    EXPECT_NEAR(computeRelRmse(test, reference, kRelRmseBlock), 0.0, 1e-7);
    EXPECT_NEAR(computeRelRmse(test, reference, 1), 0.2, 1e-7);
    EXPECT_NEAR(computeEnergyRatio(test, reference), 1.0, 1e-7);
    // A black reference has nothing to compare.
    EXPECT_THROW(computeEnergyRatio(test, Image(8, 4)), InputError);
}

} // namespace
} // namespace ispm
