// The G-buffer passes draw instances nearest first (computeDrawOrder), for a camera at a point
// and for an orthographic one looking along an axis, so the early depth test can reject what
// they hide; the order follows the eye, not the scene's listing.
#include "support/analytic_scenes.h"
#include "support/gl_fixture.h"

#include "render/gbuffer.h"
#include "render/gpu_scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>
#include <vector>

namespace ispm::test {
namespace {

constexpr int kLightResolution = 64; // no lights: any valid size

class GBufferDrawOrderTest : public GlTest {};

// The grey square, instanced at each depth (z) in turn.
Scene makeSquaresAt(const std::vector<float>& depths) {
    std::vector<glm::mat4> placements;
    for (const float z : depths)
        placements.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, z)));
    return makeGreySquares(placements);
}

TEST_F(GBufferDrawOrderTest, InstancesNearestTheEyeComeFirst) {
    const GpuScene scene(makeSquaresAt({-2.0f, -10.0f, -5.0f, 4.0f}), kLightResolution);
    // A camera at the origin: 2 m, 4 m (behind it counts by distance too), 5 m, 10 m.
    EXPECT_EQ(computeDrawOrder(scene, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)),
              (std::vector<uint32_t>{0, 3, 2, 1}));
    // An orthographic eye far along +z: the largest z first; along -z the smallest.
    EXPECT_EQ(computeDrawOrder(scene, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)),
              (std::vector<uint32_t>{3, 0, 2, 1}));
    EXPECT_EQ(computeDrawOrder(scene, glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)),
              (std::vector<uint32_t>{1, 2, 0, 3}));
}

TEST_F(GBufferDrawOrderTest, EquallyFarInstancesKeepTheirOrder) {
    const GpuScene scene(makeSquaresAt({-3.0f, 3.0f, -3.0f}), kLightResolution);
    EXPECT_EQ(computeDrawOrder(scene, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)),
              (std::vector<uint32_t>{0, 1, 2}));
}

} // namespace
} // namespace ispm::test
