// The filter guide's normal code (shared/filter_guide.h): a whole number a float holds exactly,
// and a normal back within a small angle, on both hemispheres, the axes and the octahedron's
// folds.
#include <shared/filter_guide.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace ispm {
namespace {

std::vector<glm::vec3> makeTestNormals() {
    std::vector<glm::vec3> normals = {{1, 0, 0},  {-1, 0, 0},   {0, 1, 0},  {0, -1, 0},
                                      {0, 0, 1},  {0, 0, -1},   {1, 1, -1}, {-1, 1, -1},
                                      {1, -1, 1}, {-1, -1, -1}, {1, 0, -1}, {0, -1, -1}};
    std::mt19937 rng(7);
    std::normal_distribution<float> gauss;
    for (int i = 0; i < 20000; ++i)
        normals.emplace_back(gauss(rng), gauss(rng), gauss(rng));
    for (glm::vec3& n : normals)
        n = glm::normalize(n);
    return normals;
}

TEST(FilterGuide, NormalCodesAreWholeNumbersBelowTwoToTheTwentyFour) {
    for (const glm::vec3& n : makeTestNormals()) {
        const float code = gpu::encodeGuideNormal(n);
        ASSERT_EQ(code, std::floor(code)) << n.x << " " << n.y << " " << n.z;
        ASSERT_GE(code, 0.0f);
        ASSERT_LT(code, 16777216.0f); // 2^24: every whole number below is a float
        ASSERT_NE(code, gpu::kGuideNoSurface);
    }
}

TEST(FilterGuide, NormalsComeBackWithinATenthOfADegree) {
    // 4,095 steps over [-1, 1] an axis: a step of 4.9e-4 on the octahedron, where angles
    // stretch by up to ~3x (near the octahedron's vertices): measured 1.09e-3 rad at worst.
    // Bound 1.5e-3 rad (0.086 degrees): the filter's normal weight cos^64 then moves by under
    // 64 (1.5e-3)^2 / 2 = 7.2e-5.
    double worst = 0.0;
    for (const glm::vec3& n : makeTestNormals()) {
        const glm::vec3 back = gpu::decodeGuideNormal(gpu::encodeGuideNormal(n));
        ASSERT_NEAR(glm::length(back), 1.0f, 1e-6f);
        const double angle = std::acos(std::min(1.0, double(glm::dot(n, back))));
        worst = std::max(worst, angle);
    }
    std::printf("worst angle %.3g rad\n", worst);
    EXPECT_LT(worst, 1.5e-3);
    EXPECT_GT(worst, 0.0); // quantised, so some error shows: the test sees the code at work
}

} // namespace
} // namespace ispm
