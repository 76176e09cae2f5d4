// Light cameras: every surface a light can reach must land inside its camera's image.
#include "render/light_cameras.h"

#include "bvh/bvh_scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <random>

namespace ispm::test {
namespace {

Scene makeBoxScene() {
    Scene scene;
    Mesh mesh;
    mesh.positions = {{-5, 0, -3}, {7, 0, -3}, {7, 4, 9}, {-5, 4, 9}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.triangleMaterials = {0, 0};
    scene.meshes.push_back(mesh);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    return scene;
}

glm::vec3 projectToNdc(const LightCamera& cam, const glm::vec3& p) {
    const glm::vec4 clip = cam.getClipFromWorld() * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

bool isInside(const glm::vec3& ndc) {
    constexpr float kSlack = 1e-4f; // float round-off at the frustum boundary
    return glm::all(glm::lessThanEqual(glm::abs(ndc), glm::vec3(1.0f + kSlack)));
}

TEST(LightCameras, SunOrthographicEnclosesSceneBounds) {
    Scene scene = makeBoxScene();
    Light sun;
    sun.type = LightType::Sun;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    scene.lights.push_back(sun);
    const auto cams = computeLightCameras(scene, 256);
    ASSERT_EQ(cams.size(), 1u);
    EXPECT_TRUE(cams[0].isOrthographic);
    const Aabb b = scene.computeWorldBounds();
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 c((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y,
                          (i & 4) ? b.hi.z : b.lo.z);
        EXPECT_TRUE(isInside(projectToNdc(cams[0], c))) << i;
    }
    // Texel size: the footprint width divided by the resolution.
    const glm::vec3 a = projectToNdc(cams[0], b.getCenter());
    const glm::vec3 moved = projectToNdc(
        cams[0], b.getCenter() + glm::normalize(glm::cross(sun.direction, glm::vec3(0, 0, 1))) *
                                     cams[0].texelSizeM);
    EXPECT_NEAR(glm::length(glm::vec2(moved - a)), 2.0f / 256.0f, 1e-4f);
}

TEST(LightCameras, FittedSunViewIsFinerAndHoldsWhatTheViewerSees) {
    Scene scene = makeBoxScene();
    Light light;
    light.type = LightType::Sun;
    light.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    scene.lights.push_back(light);
    const LightCamera sun = computeLightCameras(scene, 256).at(0);
    // A viewer that sees a 1 m patch of the 12 m x 12 m slope.
    std::vector<glm::vec3> visible;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j)
            visible.push_back(glm::vec3(1.0f + 0.25f * float(i), (8.0f + 0.25f * float(j)) / 3.0f,
                                        5.0f + 0.25f * float(j))); // on the slope
    const std::optional<LightCamera> fine = fitSunView(sun, visible, 256);
    ASSERT_TRUE(fine.has_value());
    EXPECT_TRUE(fine->isShadowOnly);
    EXPECT_FALSE(sun.isShadowOnly);
    EXPECT_EQ(fine->lightIndex, sun.lightIndex);
    // The patch (1.4 m across seen from the sun, with margins) against a 19 m square.
    EXPECT_LT(fine->texelSizeM, sun.texelSizeM / 8.0f);
    for (const glm::vec3& p : visible) {
        const glm::vec3 ndc = projectToNdc(*fine, p);
        // Inside, and off the border (the shadow test keeps to 1 - 4 texels).
        EXPECT_LT(std::max(std::abs(ndc.x), std::abs(ndc.y)), 1.0f - 8.0f / 256.0f);
        // The same depth as in the sun's own view: every occluder it holds is held.
        EXPECT_NEAR(ndc.z, projectToNdc(sun, p).z, 1e-4f);
    }
    // Stable: the same points moved a little (an object moving, the camera creeping) give the
    // same texel size and a square moved by whole texels, so the texel grid, and the shadow
    // edges on it, stay put.
    std::vector<glm::vec3> moved = visible;
    for (glm::vec3& p : moved)
        p += glm::vec3(0.013f, 0.0f, 0.021f);
    moved.push_back(visible.back() + glm::vec3(0.05f, 0.0f, 0.0f)); // and the patch a bit wider
    const std::optional<LightCamera> again = fitSunView(sun, moved, 256);
    ASSERT_TRUE(again.has_value());
    EXPECT_EQ(again->texelSizeM, fine->texelSizeM);
    const glm::vec2 shiftTexels =
        (glm::vec2(again->clipFromView[3]) - glm::vec2(fine->clipFromView[3])) * 0.5f * 256.0f;
    EXPECT_NEAR(shiftTexels.x, std::round(shiftTexels.x), 1e-2f);
    EXPECT_NEAR(shiftTexels.y, std::round(shiftTexels.y), 1e-2f);
    // A viewer that sees the whole slope gains too little: no second view, nor with nothing.
    const std::vector<glm::vec3> everything = {{-5, 0, -3}, {7, 0, -3}, {7, 4, 9}, {-5, 4, 9}};
    EXPECT_FALSE(fitSunView(sun, everything, 256).has_value());
    EXPECT_FALSE(fitSunView(sun, {}, 256).has_value());
}

TEST(LightCameras, VisiblePointsAreTheViewersFirstHits) {
    Scene scene = makeBoxScene();
    const BvhScene bvh = buildSceneBvh(scene);
    Camera camera;
    camera.position = {1.0f, 10.0f, 3.0f};
    camera.target = {1.0f, 2.0f, 3.0f}; // straight down onto the slope y = (z + 3) / 3
    camera.up = {0.0f, 0.0f, 1.0f};
    camera.fovYDeg = 30.0f;
    const std::vector<glm::vec3> points = sampleVisiblePoints(bvh, scene, camera, 1.0f, 8);
    ASSERT_EQ(points.size(), 64u); // every ray meets the slope
    for (const glm::vec3& p : points)
        EXPECT_NEAR(p.y, (p.z + 3.0f) / 3.0f, 1e-4f); // on the slope
}

TEST(LightCameras, SpotFrustumContainsItsCone) {
    Scene scene = makeBoxScene();
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1, 10, 2};
    spot.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    spot.innerDeg = 20;
    spot.outerDeg = 55;
    scene.lights.push_back(spot);
    const auto cams = computeLightCameras(scene, 128);
    ASSERT_EQ(cams.size(), 1u);
    // Directions just inside the outer cone, all around it, project inside the image.
    const glm::vec3 axis = spot.direction;
    const glm::vec3 u = glm::normalize(glm::cross(axis, glm::vec3(1, 0, 0)));
    const glm::vec3 v = glm::cross(axis, u);
    const float angle = glm::radians(spot.outerDeg - 0.01f);
    for (int k = 0; k < 64; ++k) {
        const float phi = glm::two_pi<float>() * float(k) / 64.0f;
        const glm::vec3 dir =
            std::cos(angle) * axis + std::sin(angle) * (std::cos(phi) * u + std::sin(phi) * v);
        EXPECT_TRUE(isInside(projectToNdc(cams[0], spot.position + dir * 5.0f))) << k;
    }
}

TEST(LightCameras, PointLightFacesCoverEveryDirection) {
    Scene scene = makeBoxScene();
    Light point;
    point.type = LightType::Point;
    point.position = {1, 2, 3};
    scene.lights.push_back(point);
    const auto cams = computeLightCameras(scene, 64);
    ASSERT_EQ(cams.size(), 6u);
    std::mt19937 rng(7);
    std::normal_distribution<float> normal;
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 dir = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
        const glm::vec3 p = point.position + dir * 3.0f;
        int covering = 0;
        for (const LightCamera& cam : cams)
            covering += isInside(projectToNdc(cam, p)) && glm::dot(dir, cam.axis) > 0.0f;
        EXPECT_GE(covering, 1) << "direction " << dir.x << "," << dir.y << "," << dir.z;
    }
}

} // namespace
} // namespace ispm::test
