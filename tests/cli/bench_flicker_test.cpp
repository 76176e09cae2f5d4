// FlickerMeter on made-up frames: a pixel alternating between 1 and 3 has a sample standard
// deviation of sqrt(2) around a mean of 2; pixels near a moving instance's box are left out of
// "away"; pixels without a surface count nowhere.
#include "cli/bench_flicker.h"

#include "scene/mesh_builder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ispm {
namespace {

// A scene with one animated unit box at the origin (the meter reads only its box).
Scene makeMovingBoxScene() {
    Scene scene;
    Mesh box;
    appendBox(box, glm::vec3(-0.5f), glm::vec3(0.5f), 0);
    scene.meshes.push_back(box);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    InstanceAnimation moving;
    moving.instanceIndex = 0;
    scene.instanceAnimations.push_back(moving);
    return scene;
}

TEST(FlickerMeter, StandardDeviationOverMeanAwayFromMovingObjects) {
    const Scene scene = makeMovingBoxScene();
    // Three pixels: on the box's face (near), 2 m away (away), and no surface.
    const std::vector<glm::vec4> positions = {
        {0.5f, 0.0f, 0.0f, 1.0f}, {2.5f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 0.0f}};
    FlickerMeter meter(0.5);
    for (int f = 0; f < 4; ++f) {
        Image frame(3, 1);
        const float light = f % 2 == 0 ? 1.0f : 3.0f;
        frame.pixels[0] = glm::vec3(light);          // flickers
        frame.pixels[1] = glm::vec3(2.0f);           // steady
        frame.pixels[2] = glm::vec3(100.0f * light); // background: ignored
        meter.addFrame(frame, positions, scene);
    }
    const FlickerResult r = meter.getResult();
    EXPECT_EQ(r.frames, 4);
    EXPECT_EQ(r.pixels, 2u);
    EXPECT_EQ(r.awayPixels, 1u);
    // Pixel 0: values 1, 3, 1, 3: mean 2, sample variance 4 / 3. Both pixels' mean is 2.
    const double deviation = std::sqrt(4.0 / 3.0);
    EXPECT_NEAR(r.all, deviation / (2.0 + 2.0), 1e-9);
    EXPECT_NEAR(r.away, 0.0, 1e-12) << "the steady pixel far from the box";
}

} // namespace
} // namespace ispm
