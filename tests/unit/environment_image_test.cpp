// The image environment (docs/design.md "Environment"): the equirectangular mapping both ways and
// its documented landmarks, the sampling pdf against an integral over the sphere, the sampler's
// histogram against the texels' weights worked out here, and the power budgets read.
#include "scene/environment.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace ispm {
namespace {

constexpr int kWidth = 16;
constexpr int kHeight = 8;

// A map whose texels differ (a bright texel, a black row, values spread over 100x).
Image makeTestMap() {
    Image image(kWidth, kHeight);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> spread(0.01f, 1.0f);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            image.at(x, y) =
                y == 2 ? glm::vec3(0.0f) : glm::vec3(spread(rng), spread(rng), spread(rng));
        }
    }
    image.at(11, 5) = glm::vec3(40.0f, 30.0f, 20.0f);
    return image;
}

glm::vec2 getRotation(float degrees) {
    return {std::cos(glm::radians(degrees)), std::sin(glm::radians(degrees))};
}

TEST(EnvironmentImage, DirectionAndUvRoundTrip) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const float degrees : {0.0f, 37.0f, -90.0f, 180.0f}) {
        const glm::vec2 rotation = getRotation(degrees);
        for (int i = 0; i < 1000; ++i) {
            // Away from the poles, where u is undefined.
            const glm::vec2 uv(unit(rng), 0.01f + 0.98f * unit(rng));
            const glm::vec3 d = gpu::computeEnvironmentDirection(uv, rotation);
            EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
            const glm::vec2 back = gpu::computeEnvironmentUv(d, rotation);
            // u wraps at 0 = 1.
            const float du = std::abs(back.x - uv.x);
            EXPECT_LT(std::min(du, 1.0f - du), 1e-4f) << degrees << " " << uv.x << " " << uv.y;
            EXPECT_NEAR(back.y, uv.y, 1e-4f);
        }
    }
}

TEST(EnvironmentImage, ConventionLandmarks) {
    // docs/scene-format.md: the top row the zenith, the centre column -z, u = 3/4 toward +x,
    // u = 1/4 toward -x; rotation_deg 90 turns +x toward -z.
    const glm::vec2 none = getRotation(0.0f);
    EXPECT_NEAR(gpu::computeEnvironmentUv({0, 1, 0}, none).y, 0.0f, 1e-6f);
    EXPECT_NEAR(gpu::computeEnvironmentUv({0, -1, 0}, none).y, 1.0f, 1e-6f);
    const glm::vec2 front = gpu::computeEnvironmentUv({0, 0, -1}, none);
    EXPECT_NEAR(front.x, 0.5f, 1e-6f);
    EXPECT_NEAR(front.y, 0.5f, 1e-6f);
    EXPECT_NEAR(gpu::computeEnvironmentUv({1, 0, 0}, none).x, 0.75f, 1e-6f);
    EXPECT_NEAR(gpu::computeEnvironmentUv({-1, 0, 0}, none).x, 0.25f, 1e-6f);
    const glm::vec3 east = gpu::computeEnvironmentDirection({0.75f, 0.5f}, getRotation(90.0f));
    EXPECT_NEAR(east.x, 0.0f, 1e-6f);
    EXPECT_NEAR(east.z, -1.0f, 1e-6f);
}

TEST(EnvironmentImage, PdfIntegratesToOne) {
    // The midpoint rule in (cos theta, phi), whose cells do not line up with the texels: the pdf
    // is piecewise constant in (u, v), so the error is that of the cells the texel edges cut.
    const Environment environment = makeImageEnvironment(makeTestMap(), 2.0f, 25.0f);
    constexpr int kSteps = 1000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double z = -1.0 + 2.0 * (i + 0.5) / kSteps;
        const double r = std::sqrt(1.0 - z * z);
        for (int j = 0; j < kSteps; ++j) {
            const double phi = glm::two_pi<double>() * (j + 0.5) / kSteps;
            const glm::vec3 d(float(r * std::cos(phi)), float(z), float(r * std::sin(phi)));
            sum += double(computeEnvironmentImagePdf(environment, d));
        }
    }
    const double integral = sum * 2.0 * glm::two_pi<double>() / (double(kSteps) * kSteps);
    EXPECT_NEAR(integral, 1.0, 3e-3); // measured 1.0000x; halving a row's weight gives 0.9x
}

TEST(EnvironmentImage, SamplesFollowTheTexelWeights) {
    // Each texel's share of 200,000 samples against luminance x sin(theta at the row's centre)
    // over their sum, worked out here; 5 standard deviations of a binomial count each.
    const Image map = makeTestMap();
    const Environment environment = makeImageEnvironment(map, 1.0f, -60.0f);
    std::vector<double> weights(map.pixels.size());
    double total = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        const double sinTheta = std::sin(glm::pi<double>() * (y + 0.5) / kHeight);
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec3 c(map.at(x, y));
            const double luminance = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
            weights[size_t(y * kWidth + x)] = luminance * sinTheta;
            total += luminance * sinTheta;
        }
    }
    constexpr int kSamples = 200000;
    std::vector<int> counts(map.pixels.size(), 0);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const glm::vec2 rotation = getRotation(-60.0f);
    for (int i = 0; i < kSamples; ++i) {
        const EnvironmentSample s = sampleEnvironmentImage(environment, {unit(rng), unit(rng)});
        ASSERT_GT(s.pdf, 0.0f);
        // The pdf and radiance it reports are those of the direction it returns.
        EXPECT_NEAR(s.pdf, computeEnvironmentImagePdf(environment, s.toward), 2e-3f * s.pdf);
        const glm::vec2 uv = gpu::computeEnvironmentUv(s.toward, rotation);
        const int x = std::min(int(uv.x * kWidth), kWidth - 1);
        const int y = std::min(int(uv.y * kHeight), kHeight - 1);
        EXPECT_EQ(s.radiance, map.at(x, y));
        ++counts[size_t(y * kWidth + x)];
    }
    for (size_t i = 0; i < counts.size(); ++i) {
        const double p = weights[i] / total;
        const double expected = p * kSamples;
        const double sigma = std::sqrt(kSamples * p * (1.0 - p));
        EXPECT_NEAR(counts[i], expected, 5.0 * sigma + 1.0) << "texel " << i;
    }
    EXPECT_EQ(counts[size_t(2 * kWidth + 3)], 0); // the black row
}

TEST(EnvironmentImage, ConstantMapMatchesTheConstantEnvironment) {
    // Radiance, the mean the photon budget reads (the sphere's), and a black map's pdf.
    const glm::vec3 radiance(0.5f, 1.0f, 2.0f);
    const Environment image = makeImageEnvironment(Image(kWidth, kHeight, radiance), 2.0f, 10.0f);
    Environment constant;
    constant.type = EnvironmentType::Constant;
    constant.radiance = radiance * 2.0f;
    EXPECT_EQ(evaluateEnvironment(image, glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f))),
              constant.radiance);
    const EnvironmentMean a = computeEnvironmentMean(image);
    const EnvironmentMean b = computeEnvironmentMean(constant);
    EXPECT_NEAR(a.luminance, b.luminance, 1e-5 * b.luminance);
    EXPECT_DOUBLE_EQ(a.solidAngleSr, b.solidAngleSr);
    const Environment black = makeImageEnvironment(Image(kWidth, kHeight), 1.0f, 0.0f);
    EXPECT_EQ(sampleEnvironmentImage(black, {0.5f, 0.5f}).pdf, 0.0f);
    EXPECT_EQ(computeEnvironmentMean(black).luminance, 0.0);
}

} // namespace
} // namespace ispm
