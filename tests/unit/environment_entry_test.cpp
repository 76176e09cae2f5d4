// shared/environment_data.h's entry of the environment's photons into the scene's bounding box
// on the CPU: every sampled point lies on a face the ray enters by, the points are uniform over
// the box's outline seen along the ray (each face's share against its area x cosine, and
// uniform on it), and the outline's area averages a quarter of the box's surface (Cauchy's
// formula), which the photon budget relies on.
#include <shared/environment_data.h>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <array>
#include <cmath>
#include <random>

namespace ispm::test {
namespace {

using glm::vec3;

constexpr vec3 kBoxMin(-3.0f, -0.5f, 2.0f);
constexpr vec3 kExtent(6.0f, 1.5f, 4.0f); // unequal sides: each face's share differs

TEST(EnvironmentEntryTest, PointsLieOnTheFacesTheRayEntersBy) {
    std::mt19937 engine(7u);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const vec3 dir = glm::normalize(vec3(0.3f, -0.8f, -0.5f));
    std::array<int, 3> perAxis{};
    constexpr int kSamples = 200000;
    std::array<std::array<int, 4>, 3> quarters{}; // per face, points in each half of one side
    for (int i = 0; i < kSamples; ++i) {
        const vec3 u(uniform(engine), uniform(engine), uniform(engine));
        const vec3 p = gpu::sampleBoxEntry(kBoxMin, kExtent, dir, u);
        const vec3 at = (p - kBoxMin) / kExtent;
        // Inside the box (to float precision), on exactly one face facing against `dir`:
        // x = 0 where dir.x > 0 (the ray enters through the low side), else 1.
        ASSERT_TRUE(glm::all(glm::greaterThanEqual(at, vec3(-1e-6f))) &&
                    glm::all(glm::lessThanEqual(at, vec3(1.0f + 1e-6f))));
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            const float side = dir[a] > 0.0f ? 0.0f : 1.0f;
            if (std::abs(at[a] - side) < 1e-6f) axis = a;
        }
        ASSERT_GE(axis, 0) << "a point on no entry face";
        ++perAxis[size_t(axis)];
        // Uniform on the face: the first free coordinate's halves hold half the face's points.
        const int free = axis == 0 ? 1 : 0;
        ++quarters[size_t(axis)][at[free] < 0.5f ? 0 : 1];
    }
    const float outline = gpu::computeBoxOutlineArea(kExtent, dir);
    const vec3 faceArea(kExtent.y * kExtent.z, kExtent.x * kExtent.z, kExtent.x * kExtent.y);
    for (int a = 0; a < 3; ++a) {
        const double expected = std::abs(dir[a]) * faceArea[a] / outline;
        const double measured = double(perAxis[size_t(a)]) / kSamples;
        // Binomial standard deviation <= 0.0012 at 200,000 samples: 0.006 is five of them.
        EXPECT_NEAR(measured, expected, 0.006) << "face of axis " << a;
        const int onFace = perAxis[size_t(a)];
        if (onFace > 1000) {
            EXPECT_NEAR(double(quarters[size_t(a)][0]) / onFace, 0.5, 0.03) << "axis " << a;
        }
    }
}

TEST(EnvironmentEntryTest, OutlineAveragesAQuarterOfTheSurface) {
    // Midpoint rule over the sphere in (cos theta, phi), and over the upper hemisphere: both
    // mean outlines are S / 4 (GpuScene::getEnvironmentPowerW).
    constexpr int kSteps = 256;
    double sphere = 0.0;
    double hemisphere = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double z = -1.0 + 2.0 * (i + 0.5) / kSteps;
        const double r = std::sqrt(1.0 - z * z);
        for (int j = 0; j < kSteps; ++j) {
            const double phi = glm::two_pi<double>() * (j + 0.5) / kSteps;
            const vec3 dir(float(r * std::cos(phi)), float(z), float(r * std::sin(phi)));
            const double area = gpu::computeBoxOutlineArea(kExtent, dir);
            sphere += area;
            if (z > 0.0) hemisphere += area;
        }
    }
    sphere /= double(kSteps) * kSteps;
    hemisphere /= double(kSteps) * kSteps / 2.0;
    const double surface =
        2.0 * double(kExtent.x * kExtent.y + kExtent.y * kExtent.z + kExtent.z * kExtent.x);
    // The quadrature of |cos| converges as 1 / steps^2 but for the kink at 0: 0.2% is ample.
    EXPECT_NEAR(sphere / (surface / 4.0), 1.0, 0.002);
    EXPECT_NEAR(hemisphere / (surface / 4.0), 1.0, 0.002);
}

} // namespace
} // namespace ispm::test
