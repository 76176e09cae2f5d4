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

bool holds(const Aabb& box, const glm::vec3& p) {
    constexpr float kSlack = 1e-4f; // float round-off of the cone's cap, in metres
    return glm::all(glm::lessThanEqual(box.lo - kSlack, p)) &&
           glm::all(glm::lessThanEqual(p, box.hi + kSlack));
}

TEST(LightCameras, LitBoundsHoldEveryPointTheSpotLights) {
    Aabb scene;
    scene.extend(glm::vec3(-20.0f, 0.0f, -15.0f));
    scene.extend(glm::vec3(25.0f, 12.0f, 30.0f));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const auto inScene = [&] {
        return scene.lo + glm::vec3(unit(rng), unit(rng), unit(rng)) * scene.getExtent();
    };
    int lit = 0;
    for (int l = 0; l < 40; ++l) {
        Light spot;
        spot.type = LightType::Spot;
        // Inside the scene and outside it, in every direction, narrow to nearly kMaxBoundedSpotDeg.
        spot.position = scene.getCenter() + (glm::vec3(unit(rng), unit(rng), unit(rng)) - 0.5f) *
                                                scene.getExtent() * 1.6f;
        spot.direction =
            glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) - 0.5f + glm::vec3(1e-3f));
        spot.outerDeg = 5.0f + 79.0f * unit(rng);
        spot.innerDeg = 0.5f * spot.outerDeg;
        const std::optional<Aabb> box = computeLitBounds(spot, scene);
        ASSERT_TRUE(box.has_value()) << l;
        const float cosOuter = std::cos(glm::radians(spot.outerDeg));
        for (int k = 0; k < 2000; ++k) {
            const glm::vec3 p = inScene();
            const glm::vec3 d = glm::normalize(p - spot.position);
            if (glm::dot(d, spot.direction) < cosOuter) continue;
            ++lit;
            ASSERT_TRUE(holds(*box, p)) << "spot " << l << " point " << k;
        }
    }
    EXPECT_GT(lit, 1000); // the check ran on many lit points
}

TEST(LightCameras, LitBoundsOfAStreetLightAreItsPool) {
    // A street light 9 m over a 200 m city, its 65-degree cone ending on the ground: a pool of
    // radius 9 tan(65) = 19.3 m, not the city.
    Aabb city;
    city.extend(glm::vec3(-100.0f, 0.0f, -100.0f));
    city.extend(glm::vec3(100.0f, 60.0f, 100.0f));
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {10.0f, 9.0f, -30.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.outerDeg = 65.0f;
    const std::optional<Aabb> box = computeLitBounds(spot, city);
    ASSERT_TRUE(box.has_value());
    const float pool = 9.0f * std::tan(glm::radians(65.0f));
    constexpr float kTolerance = 1e-3f; // metres: float round-off
    EXPECT_NEAR(box->lo.x, 10.0f - pool, kTolerance);
    EXPECT_NEAR(box->hi.x, 10.0f + pool, kTolerance);
    EXPECT_NEAR(box->lo.z, -30.0f - pool, kTolerance);
    EXPECT_NEAR(box->hi.z, -30.0f + pool, kTolerance);
    EXPECT_NEAR(box->lo.y, 0.0f, kTolerance);
    EXPECT_NEAR(box->hi.y, 9.0f, kTolerance);
}

TEST(LightCameras, LitBoundsOnlyForSpotsThatLightPartOfTheScene) {
    Aabb scene;
    scene.extend(glm::vec3(-1.0f));
    scene.extend(glm::vec3(1.0f));
    Light light;
    light.position = {0.0f, 3.0f, 0.0f};
    light.direction = {0.0f, -1.0f, 0.0f};
    light.outerDeg = 30.0f;
    light.type = LightType::Point;
    EXPECT_FALSE(computeLitBounds(light, scene).has_value());
    light.type = LightType::Sun;
    EXPECT_FALSE(computeLitBounds(light, scene).has_value());
    light.type = LightType::Spot;
    light.outerDeg = kMaxBoundedSpotDeg;
    EXPECT_FALSE(computeLitBounds(light, scene).has_value()); // as wide as a point light
    light.outerDeg = 30.0f;
    light.direction = {0.0f, 1.0f, 0.0f}; // pointing away from the scene
    const std::optional<Aabb> away = computeLitBounds(light, scene);
    ASSERT_TRUE(away.has_value());
    EXPECT_TRUE(away->isEmpty());
    light.position = {5.0f, 0.0f, 0.0f}; // beside it, its cone passing by
    light.direction = {0.0f, 0.0f, 1.0f};
    const std::optional<Aabb> beside = computeLitBounds(light, scene);
    ASSERT_TRUE(beside.has_value());
    EXPECT_TRUE(beside->isEmpty());
}

} // namespace
} // namespace ispm::test
