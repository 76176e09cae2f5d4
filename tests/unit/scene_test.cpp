// The scene model and loader on good input: values survive the trip from JSON, transforms follow
// the documented order, the shipped scenes load, and the camera and spot-light math hold.
#include "core/strings.h"
#include "scene/cornell_box.h"
#include "scene_test_util.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace ispm::test {
namespace {

using nlohmann::json;

constexpr float kTolerance = 1e-5f;

bool isNear(const glm::vec3& a, const glm::vec3& b, float tolerance = kTolerance) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
}

glm::vec3 transformPoint(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec3(m * glm::vec4(p, 1.0f));
}

const char* const kFullScene = R"({
    "name": "everything",
    "description": "every key of the format once",
    "camera": {"position": [1, 2, 3], "target": [1, 2, 0], "up": [0, 2, 0], "fov_y_deg": 35.5,
               "near": 0.05, "far": 500},
    "background": [0.1, 0.2, 0.3],
    "materials": {
        "glass": {"specular": [0.1, 0.1, 0.1], "transmissive": [0.9, 0.9, 0.8], "ior": 1.33,
                  "phong_exponent": 200},
        "lamp": {"diffuse": [0.5, 0.5, 0.5], "emission": [10, 9, 8]}
    },
    "objects": [
        {"type": "mesh", "name": "tri", "material": "glass",
         "triangles": [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]],
         "translate": [1, 2, 3], "rotate_deg": [90, 0, 0], "scale": 2},
        {"type": "mesh", "material": {"diffuse": [0.2, 0.4, 0.6]},
         "quads": [[[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]],
         "matrix": [[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7], [0, 0, 0, 1]]},
        {"type": "box", "material": "lamp", "min": [-1, -2, -3], "max": [1, 2, 3],
         "rotate_deg": [90, 90, 0]},
        {"type": "box", "material": "lamp", "min": [0, 0, 0], "max": [1, 1, 1],
         "matrix": [1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, -4,  0, 0, 0, 1], "scale": [1, 2, 3]}
    ],
    "lights": [
        {"type": "point", "position": [0, 5, 0], "intensity": [100, 90, 80], "photon_share": 2},
        {"type": "spot", "position": [1, 4, 1], "direction": [0, -2, 0], "intensity": [7, 7, 7],
         "inner_deg": 20, "outer_deg": 45},
        {"type": "sun", "direction": [1, -1, 0], "irradiance": [1000, 900, 800]}
    ],
    "render": {"width": 320, "exposure": -1.5, "tonemap": "filmic"}
})";

TEST(SceneLoader, FullSceneRoundTripsValues) {
    ScratchDir dir;
    json doc = json::parse(kFullScene);
    // The last object mixes matrix and TRS on purpose elsewhere; here it must not.
    doc["objects"][3].erase("scale");
    const Scene scene = loadScene(dir.write("full.json", doc.dump()));

    EXPECT_TRUE(isNear(scene.camera.position, {1, 2, 3}));
    EXPECT_TRUE(isNear(scene.camera.target, {1, 2, 0}));
    EXPECT_TRUE(isNear(scene.camera.up, {0, 1, 0})); // normalised on load
    EXPECT_FLOAT_EQ(scene.camera.fovYDeg, 35.5f);
    EXPECT_FLOAT_EQ(scene.camera.nearM, 0.05f);
    EXPECT_FLOAT_EQ(scene.camera.farM, 500.0f);
    EXPECT_TRUE(isNear(scene.background, {0.1f, 0.2f, 0.3f}));

    ASSERT_EQ(scene.materials.size(), 3u); // glass, lamp, the inline one
    const Material& glass = scene.materials[0];
    EXPECT_EQ(glass.name, "glass");
    EXPECT_TRUE(isNear(glass.transmissive, {0.9f, 0.9f, 0.8f}));
    EXPECT_TRUE(isNear(glass.specular, {0.1f, 0.1f, 0.1f}));
    EXPECT_FLOAT_EQ(glass.ior, 1.33f);
    EXPECT_FLOAT_EQ(glass.phongExponent, 200.0f);
    EXPECT_TRUE(isNear(glass.diffuse, {0, 0, 0})); // defaults are zero ...
    EXPECT_FLOAT_EQ(scene.materials[1].ior, 1.5f); // ... but ior is 1.5
    EXPECT_TRUE(isNear(scene.materials[1].emission, {10, 9, 8}));
    EXPECT_EQ(scene.materials[2].name, "/objects/1/material");
    EXPECT_TRUE(isNear(scene.materials[2].diffuse, {0.2f, 0.4f, 0.6f}));

    ASSERT_EQ(scene.meshes.size(), 4u);
    ASSERT_EQ(scene.instances.size(), 4u);
    EXPECT_EQ(scene.meshes[0].name, "tri");
    EXPECT_EQ(scene.meshes[1].name, "object_1");
    EXPECT_EQ(scene.meshes[0].triangles.size(), 1u);
    EXPECT_EQ(scene.meshes[1].triangles.size(), 2u); // a quad is two triangles
    EXPECT_EQ(scene.meshes[2].triangles.size(), 12u);
    EXPECT_EQ(scene.meshes[1].triangleMaterials, (std::vector<uint32_t>{2, 2}));
    EXPECT_EQ(scene.countTriangles(), 1u + 2u + 12u + 12u);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        EXPECT_EQ(scene.instances[i].meshIndex, i); // one mesh + one instance per object
    }

    // Meshes stay in object space; the instance holds the transform.
    EXPECT_TRUE(isNear(scene.meshes[0].positions[2], {0, 1, 0}));
    // T R S: (0,1,0) scaled by 2, turned 90 degrees about x to (0,0,2), moved by (1,2,3).
    EXPECT_TRUE(isNear(transformPoint(scene.instances[0].worldFromObject, {0, 1, 0}), {1, 2, 5}));
    // Row-major matrix: the last column is the translation.
    EXPECT_TRUE(isNear(transformPoint(scene.instances[1].worldFromObject, {0, 0, 0}), {5, 6, 7}));
    // Rx first, then Ry: +y goes to +z, then to +x.
    EXPECT_TRUE(isNear(transformPoint(scene.instances[2].worldFromObject, {0, 1, 0}), {1, 0, 0}));
    EXPECT_TRUE(isNear(transformPoint(scene.instances[3].worldFromObject, {0, 0, 0}), {0, 0, -4}));

    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].type, LightType::Point);
    EXPECT_TRUE(isNear(scene.lights[0].intensity, {100, 90, 80}));
    EXPECT_FLOAT_EQ(scene.lights[0].photonShare, 2.0f);
    EXPECT_LT(scene.lights[1].photonShare, 0.0f); // not given: derived later
    EXPECT_EQ(scene.lights[1].type, LightType::Spot);
    EXPECT_TRUE(isNear(scene.lights[1].direction, {0, -1, 0}));
    EXPECT_FLOAT_EQ(scene.lights[1].innerDeg, 20.0f);
    EXPECT_FLOAT_EQ(scene.lights[1].outerDeg, 45.0f);
    EXPECT_EQ(scene.lights[2].type, LightType::Sun);
    EXPECT_TRUE(isNear(scene.lights[2].direction, glm::normalize(glm::vec3(1, -1, 0))));
    EXPECT_TRUE(isNear(scene.lights[2].irradiance, {1000, 900, 800}));

    EXPECT_EQ(scene.settings.getInt("width"), 320);
    EXPECT_FLOAT_EQ(scene.settings.getFloat("exposure"), -1.5f);
    EXPECT_EQ(scene.settings.getEnum("tonemap"), "filmic");
    EXPECT_FALSE(scene.settings.isSet("height"));
}

TEST(SceneLoader, MatrixWithTrsIsRejected) {
    ScratchDir dir;
    const std::string message = getLoadError(dir, kFullScene, "mixed.json");
    EXPECT_TRUE(contains(message, "mixed.json: /objects/3/matrix")) << message;
}

TEST(SceneLoader, ShippedScenesLoad) {
    for (const char* name : {"cornell.json", "box_city.json", "courtyard.json",
                             "courtyard_envmap.json", "dynamic.json", "caustics.json"}) {
        SCOPED_TRACE(name);
        const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/" + name);
        EXPECT_FALSE(scene.meshes.empty());
        EXPECT_GT(scene.countTriangles(), 0u);
        EXPECT_FALSE(scene.lights.empty());
        EXPECT_FALSE(scene.computeWorldBounds().isEmpty());
    }
}

TEST(SceneLoader, NamedCamerasAreChosenByName) {
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/courtyard.json");
    const glm::vec3 outside = scene.camera.position;
    selectCamera(scene, ""); // no name: the file's `camera`
    EXPECT_EQ(scene.camera.position, outside);
    selectCamera(scene, "room");
    EXPECT_NE(scene.camera.position, outside);
    // The room camera stands inside the room (x, z in [-2, 2], under its 3 m roof).
    EXPECT_LT(std::abs(scene.camera.position.x), 2.0f);
    EXPECT_LT(std::abs(scene.camera.position.z), 2.0f);
    EXPECT_LT(scene.camera.position.y, 3.0f);
    try {
        selectCamera(scene, "attic");
        FAIL() << "an unknown camera name was accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("courtyard.json: /cameras"), std::string::npos) << message;
        EXPECT_NE(message.find("'attic'"), std::string::npos) << message;
        EXPECT_NE(message.find("room"), std::string::npos) << message;
    }
}

TEST(SceneLoader, ShippedCornellSceneHasTheSpotlight) {
    const Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/cornell.json");
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& spot = scene.lights[0];
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_TRUE(isNear(spot.position, {0.278f, 0.5388f, 0.2795f}));
    EXPECT_TRUE(isNear(spot.direction, {0, -1, 0}));
    EXPECT_FLOAT_EQ(scene.camera.fovYDeg, 39.3077f);
    EXPECT_EQ(scene.materials.size(), 3u);
}

TEST(SceneLoader, FormatDocumentExamplesLoad) {
    // The examples in docs/scene-format.md are part of the reference: they must stay valid.
    std::ifstream in(std::string(ISPM_TEST_DATA_DIR) + "/../docs/scene-format.md");
    ASSERT_TRUE(in) << "docs/scene-format.md not found";
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    ScratchDir dir;
    std::filesystem::create_directories(dir.getPath("models"));
    dir.write("models/bunny.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    int exampleCount = 0;
    const std::string open = "```json\n";
    for (size_t at = doc.find(open); at != std::string::npos; at = doc.find(open, at)) {
        at += open.size();
        const size_t end = doc.find("```", at);
        ASSERT_NE(end, std::string::npos);
        const std::string path =
            dir.write(strCat("example_", exampleCount++, ".json"), doc.substr(at, end - at));
        EXPECT_NO_THROW(loadScene(path)) << doc.substr(at, end - at);
    }
    EXPECT_EQ(exampleCount, 2);
}

TEST(CornellBox, HasMeasuredBoundsAndThreeMaterials) {
    Scene scene;
    addCornellBox(scene, glm::mat4(1.0f));
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 1u);
    const Aabb bounds = scene.computeWorldBounds();
    EXPECT_TRUE(isNear(bounds.lo, {0, 0, 0}));
    EXPECT_TRUE(isNear(bounds.hi, {0.556f, 0.5488f, 0.5592f}));
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.materials[0].name, "cornell_white");
    EXPECT_EQ(scene.materials[1].name, "cornell_red");
    EXPECT_EQ(scene.materials[2].name, "cornell_green");
    EXPECT_TRUE(isNear(scene.materials[1].diffuse, {0.63f, 0.065f, 0.05f}));
    // 5 walls and 5 quads per block, two triangles each.
    EXPECT_EQ(scene.countTriangles(), 30u);

    // A second box reuses the materials; a translation moves the bounds.
    addCornellBox(scene, glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0)));
    EXPECT_EQ(scene.materials.size(), 3u);
    EXPECT_TRUE(isNear(scene.computeWorldBounds().hi, {1.556f, 0.5488f, 0.5592f}));
}

TEST(CornellBox, SceneMaterialsOverrideItsOwn) {
    ScratchDir dir;
    const Scene scene = loadScene(dir.write("c.json", R"({
        "camera": {"position": [0.278, 0.273, -0.8], "target": [0.278, 0.273, 0]},
        "materials": {"cornell_white": {"diffuse": [0.5, 0.5, 0.5]}},
        "objects": [{"type": "cornell_box", "name": "box", "translate": [0, 1, 0]}]
    })"));
    EXPECT_EQ(scene.materials.size(), 3u);
    EXPECT_TRUE(isNear(scene.materials[0].diffuse, {0.5f, 0.5f, 0.5f}));
    EXPECT_EQ(scene.meshes[0].name, "box");
    EXPECT_TRUE(isNear(scene.computeWorldBounds().lo, {0, 1, 0}));
    EXPECT_TRUE(scene.lights.empty());            // lights are optional
    EXPECT_FLOAT_EQ(scene.camera.fovYDeg, 45.0f); // the documented default
}

TEST(SpotFalloff, IsOneInsideZeroOutsideHalfAtMiddleAndMonotone) {
    constexpr float kInnerDeg = 20.0f;
    constexpr float kOuterDeg = 40.0f;
    const auto falloffAt = [&](float deg) {
        return computeSpotFalloff(std::cos(glm::radians(deg)), kInnerDeg, kOuterDeg);
    };
    EXPECT_FLOAT_EQ(falloffAt(0.0f), 1.0f);
    EXPECT_FLOAT_EQ(falloffAt(19.9f), 1.0f);
    EXPECT_FLOAT_EQ(falloffAt(40.1f), 0.0f);
    EXPECT_FLOAT_EQ(falloffAt(90.0f), 0.0f);
    // s = 0.5 halfway between the cosines: smoothstep gives exactly 0.5.
    const float cosMiddle =
        0.5f * (std::cos(glm::radians(kInnerDeg)) + std::cos(glm::radians(kOuterDeg)));
    EXPECT_NEAR(computeSpotFalloff(cosMiddle, kInnerDeg, kOuterDeg), 0.5f, 1e-5f);
    constexpr float kStepDeg = 0.25f;
    float previous = 1.0f;
    for (float deg = 0.0f; deg <= 60.0f; deg += kStepDeg) {
        const float s = falloffAt(deg);
        EXPECT_LE(s, previous) << deg;
        EXPECT_GE(s, 0.0f);
        previous = s;
    }
}

TEST(SpotFalloff, EqualAnglesGiveAHardEdge) {
    EXPECT_FLOAT_EQ(computeSpotFalloff(std::cos(glm::radians(29.0f)), 30.0f, 30.0f), 1.0f);
    EXPECT_FLOAT_EQ(computeSpotFalloff(std::cos(glm::radians(31.0f)), 30.0f, 30.0f), 0.0f);
}

glm::vec3 projectToNdc(const glm::mat4& clipFromWorld, const glm::vec3& p) {
    const glm::vec4 clip = clipFromWorld * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

TEST(CameraMath, TargetAtCentreRightIsForwardCrossUp) {
    Camera camera;
    camera.position = {1, 2, 3};
    camera.target = {4, 2.5f, -1};
    camera.up = {0, 1, 0};
    camera.fovYDeg = 60.0f;
    constexpr float kAspect = 1.5f;
    constexpr float kNear = 0.1f;
    constexpr float kFar = 100.0f;
    const glm::mat4 clipFromWorld =
        computeClipFromView(camera, kAspect, kNear, kFar) * computeViewFromWorld(camera);

    const glm::vec3 centre = projectToNdc(clipFromWorld, camera.target);
    EXPECT_NEAR(centre.x, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.y, 0.0f, 1e-5f);

    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 trueUp = glm::cross(right, forward);
    const glm::vec3 toRight = projectToNdc(clipFromWorld, camera.target + 0.1f * right);
    EXPECT_GT(toRight.x, 0.0f);
    EXPECT_NEAR(toRight.y, 0.0f, 1e-5f);

    // A point on the top edge of the view: the full vertical field of view is fov_y_deg.
    const float distance = glm::length(camera.target - camera.position);
    const glm::vec3 top =
        camera.target + distance * std::tan(glm::radians(0.5f * camera.fovYDeg)) * trueUp;
    EXPECT_NEAR(projectToNdc(clipFromWorld, top).y, 1.0f, 1e-4f);

    const glm::mat4 expected = glm::perspective(glm::radians(60.0f), kAspect, kNear, kFar) *
                               glm::lookAt(camera.position, camera.target, camera.up);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            EXPECT_FLOAT_EQ(clipFromWorld[c][r], expected[c][r]);
    }
}

} // namespace
} // namespace ispm::test
