// The radii of radius_mode travel and path_density (shared/photon_data.h computeTravelRadius):
// travel grows linearly with the distance travelled between its two ends; path_density depends on
// the path alone (McGuire and Luebke 2009), radius_max over the square root of its density.
#include <shared/photon_data.h>

#include <gtest/gtest.h>

namespace ispm {
namespace {

// radius_min 0.02 m, radius_max 0.08 m, dist_min 1 m, dist_max 5 m.
constexpr gpu::TravelRadii kRadii{
    .radiusMinM = 0.02f, .radiusMaxM = 0.08f, .distMinM = 1.0f, .distMaxM = 5.0f};

TEST(TravelRadius, GrowsLinearlyBetweenDistMinAndDistMax) {
    EXPECT_FLOAT_EQ(gpu::computeTravelRadius(0.0f, 1.0f, kRadii, gpu::kRadiusTravel), 0.02f);
    EXPECT_FLOAT_EQ(gpu::computeTravelRadius(1.0f, 1.0f, kRadii, gpu::kRadiusTravel), 0.02f);
    EXPECT_FLOAT_EQ(gpu::computeTravelRadius(3.0f, 1.0f, kRadii, gpu::kRadiusTravel), 0.05f);
    EXPECT_FLOAT_EQ(gpu::computeTravelRadius(5.0f, 1.0f, kRadii, gpu::kRadiusTravel), 0.08f);
    EXPECT_FLOAT_EQ(gpu::computeTravelRadius(50.0f, 1.0f, kRadii, gpu::kRadiusTravel), 0.08f);
    // The path's density does not enter.
    EXPECT_FLOAT_EQ(gpu::computeTravelRadius(3.0f, 16.0f, kRadii, gpu::kRadiusTravel), 0.05f);
}

TEST(TravelRadius, PathDensityRadiusIgnoresTravelAndShrinksWithFocus) {
    for (float travelled : {0.0f, 3.0f, 50.0f}) {
        // A path of diffuse bounces (density 1, or below: never wider) splats at radius_max.
        EXPECT_FLOAT_EQ(gpu::computeTravelRadius(travelled, 1.0f, kRadii, gpu::kRadiusPathDensity),
                        0.08f);
        EXPECT_FLOAT_EQ(gpu::computeTravelRadius(travelled, 0.5f, kRadii, gpu::kRadiusPathDensity),
                        0.08f);
        // Four times as focused: half the radius.
        EXPECT_FLOAT_EQ(gpu::computeTravelRadius(travelled, 4.0f, kRadii, gpu::kRadiusPathDensity),
                        0.04f);
        // Never below radius_min.
        EXPECT_FLOAT_EQ(gpu::computeTravelRadius(travelled, 1e6f, kRadii, gpu::kRadiusPathDensity),
                        0.02f);
    }
}

} // namespace
} // namespace ispm
