// The viewer camera's clip planes: derived ones enclose the scene at any scale (a scene a few
// micrometres across is not clipped by a near plane fixed in metres), and set ones the depth
// buffer cannot use (a near plane of 1e-8 m under a far plane of 3e38 m put every depth on the
// far plane: a black image) are brought within its range, with a warning.
#include "render/frame_constants.h"

#include <gtest/gtest.h>

#include <vector>

namespace ispm::test {
namespace {

Camera makeCamera(float distanceM) {
    Camera camera;
    camera.position = {0.0f, 0.0f, distanceM};
    camera.target = {0.0f, 0.0f, 0.0f};
    return camera;
}

Aabb makeCube(float halfM) {
    Aabb box;
    box.extend(glm::vec3(-halfM));
    box.extend(glm::vec3(halfM));
    return box;
}

TEST(CameraRange, DerivedPlanesEncloseTheSceneAtAnyScale) {
    for (float half : {1e-6f, 1e-3f, 1.0f, 1e3f}) {
        const Camera camera = makeCamera(3.0f * half);
        float nearM = 0.0f;
        float farM = 0.0f;
        computeCameraRange(camera, makeCube(half), {}, nearM, farM);
        EXPECT_LT(nearM, 2.0f * half) << half << ": the nearest face is 2 half-sizes away";
        EXPECT_GT(farM, 4.0f * half) << half << ": the farthest corner is past 4 half-sizes";
        EXPECT_GT(nearM, 0.0f) << half;
        EXPECT_EQ(describeRaisedNearPlane(camera, makeCube(half), {}), "") << half;
    }
}

TEST(CameraRange, PlanesBeyondTheDepthBuffersRangeAreBroughtIn) {
    Camera camera = makeCamera(3.0f);
    camera.nearM = 1e-8f;
    camera.farM = 3e38f;
    float nearM = 0.0f;
    float farM = 0.0f;
    computeCameraRange(camera, makeCube(1.0f), {}, nearM, farM);
    // Far comes in to the derived plane (nothing lies further), near rises to 1e-5 of it.
    float derivedNear = 0.0f;
    float derivedFar = 0.0f;
    computeCameraRange(makeCamera(3.0f), makeCube(1.0f), {}, derivedNear, derivedFar);
    EXPECT_EQ(farM, derivedFar);
    EXPECT_FLOAT_EQ(nearM, farM * kMinNearToFar);
    const std::string warning = describeRaisedNearPlane(camera, makeCube(1.0f), {});
    EXPECT_NE(warning.find("near plane (1e-08 m) is raised"), std::string::npos) << warning;
    // Planes within the range are kept as set.
    camera.nearM = 0.05f;
    camera.farM = 4.5f;
    computeCameraRange(camera, makeCube(1.0f), {}, nearM, farM);
    EXPECT_EQ(nearM, 0.05f);
    EXPECT_EQ(farM, 4.5f);
    EXPECT_EQ(describeRaisedNearPlane(camera, makeCube(1.0f), {}), "");
}

TEST(CameraRange, AHugeDistantPartLeavesTheNearPlaneToTheNearOne) {
    // A 2 m room 3 m in front of the eye and a 1e6 m block 5e6 m away: the far plane reaches
    // the block, and 1e-4 of it (700 m) would clip the room away; the room's half distance
    // bounds the near plane instead.
    const Camera camera = makeCamera(3.0f);
    Aabb block;
    block.extend(glm::vec3(-5e5f, -5e5f, -5.5e6f));
    block.extend(glm::vec3(5e5f, 5e5f, -4.5e6f));
    Aabb all = makeCube(1.0f);
    all.extend(block.lo);
    all.extend(block.hi);
    const std::vector<Aabb> parts = {makeCube(1.0f), block};
    float nearM = 0.0f;
    float farM = 0.0f;
    computeCameraRange(camera, all, parts, nearM, farM);
    EXPECT_GT(farM, 5.5e6f);
    EXPECT_LT(nearM, 2.0f) << "the room's nearest face";
    EXPECT_GT(nearM, 0.0f);
    // Inside a part, its own depth bounds the near plane.
    computeCameraRange(makeCamera(0.5f), all, parts, nearM, farM);
    EXPECT_LT(nearM, 1e-3f);
    EXPECT_GT(nearM, 0.0f);
}

} // namespace
} // namespace ispm::test
