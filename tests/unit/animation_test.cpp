// Animation: the scene format's `animation` key (parsing and errors naming file and JSON path)
// and Scene::update (deterministic, periodic, composed after the static transform).
#include "scene_test_util.h"

#include <glm/gtc/matrix_transform.hpp>

#include <vector>

namespace ispm::test {
namespace {

using nlohmann::json;

constexpr float kTolerance = 1e-5f; // float matrices after a few rotations

// One box and a spot and a sun; `objectAnimation` and the lights' animations are set per test.
json makeScene(const json& objectAnimation, const json& spotAnimation = nullptr,
               const json& sunAnimation = nullptr) {
    json doc = json::parse(R"({
        "camera": {"position": [0, 1, -5], "target": [0, 0, 0]},
        "materials": {"white": {"diffuse": [0.8, 0.8, 0.8]}},
        "objects": [{"type": "box", "material": "white", "min": [-0.5, 0, -0.5],
                     "max": [0.5, 1, 0.5], "translate": [3, 0, 0], "rotate_deg": [0, 90, 0],
                     "scale": 2}],
        "lights": [
            {"type": "spot", "position": [0, 2, 0], "direction": [1, 0, 0],
             "intensity": [1, 1, 1], "inner_deg": 10, "outer_deg": 20},
            {"type": "sun", "direction": [1, -1, 0], "irradiance": [1, 1, 1]}
        ]
    })");
    if (!objectAnimation.is_null()) doc["objects"][0]["animation"] = objectAnimation;
    if (!spotAnimation.is_null()) doc["lights"][0]["animation"] = spotAnimation;
    if (!sunAnimation.is_null()) doc["lights"][1]["animation"] = sunAnimation;
    return doc;
}

Scene load(const json& doc) {
    return parseScene(doc, "anim.json", ".");
}

glm::mat4 getStaticTransform() {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(3, 0, 0));
    m = glm::rotate(m, glm::radians(90.0f), glm::vec3(0, 1, 0));
    return glm::scale(m, glm::vec3(2.0f));
}

void expectNear(const glm::mat4& a, const glm::mat4& b) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[c][r], b[c][r], kTolerance) << c << "," << r;
    }
}

void expectNear(const glm::vec3& a, const glm::vec3& b) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(a[i], b[i], kTolerance) << i;
}

TEST(AnimationTest, SceneWithoutAnimationIsStill) {
    const Scene scene = load(makeScene(nullptr));
    EXPECT_FALSE(scene.isAnimated());
    EXPECT_TRUE(scene.instanceAnimations.empty());
}

TEST(AnimationTest, TranslationComposesAfterStaticTransformInWorldSpace) {
    Scene scene = load(makeScene(json{{"translate_per_s", {0, 1, 0}}}));
    ASSERT_TRUE(scene.isAnimated());
    ASSERT_EQ(scene.instanceAnimations.size(), 1u);
    expectNear(scene.instances[0].worldFromObject, getStaticTransform()); // t = 0 on load
    scene.update(2.0);
    // World space: +2 m in world y, not along the scaled, rotated object axes.
    expectNear(scene.instances[0].worldFromObject,
               glm::translate(glm::mat4(1.0f), glm::vec3(0, 2, 0)) * getStaticTransform());
}

TEST(AnimationTest, RotationTurnsAboutTheObjectOriginByDefault) {
    Scene scene = load(makeScene(json{{"rotate_deg_per_s", {0, 45, 0}}}));
    scene.update(2.0); // 90 degrees about +y through (3, 0, 0)
    const glm::mat4& m = scene.instances[0].worldFromObject;
    expectNear(glm::vec3(m * glm::vec4(0, 0, 0, 1)), glm::vec3(3, 0, 0));
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0));
    expectNear(glm::mat3(m), glm::mat3(turn) * glm::mat3(getStaticTransform()));
}

TEST(AnimationTest, RotationAboutAPivot) {
    Scene scene = load(makeScene(json{{"rotate_deg_per_s", {0, 0, 90}}, {"pivot", {3, 1, 0}}}));
    scene.update(2.0); // 180 degrees about z through (3, 1, 0): the origin (3, 0, 0) -> (3, 2, 0)
    expectNear(glm::vec3(scene.instances[0].worldFromObject * glm::vec4(0, 0, 0, 1)),
               glm::vec3(3, 2, 0));
}

TEST(AnimationTest, OrbitReturnsToItsStartEveryPeriod) {
    constexpr double kPeriodS = 0.7; // not a binary fraction
    Scene scene = load(makeScene(
        json{{"orbit", {{"centre", {1, 0, 0}}, {"axis", {0, 1, 0}}, {"period_s", kPeriodS}}}}));
    const glm::mat4 start = scene.instances[0].worldFromObject;
    scene.update(kPeriodS / 2.0);
    // Half a turn about the vertical through (1, 0, 0): the origin (3, 0, 0) goes to (-1, 0, 0).
    expectNear(glm::vec3(scene.instances[0].worldFromObject[3]), glm::vec3(-1, 0, 0));
    for (int periods : {1, 3, 1000}) {
        scene.update(kPeriodS * periods);
        expectNear(scene.instances[0].worldFromObject, start);
    }
}

TEST(AnimationTest, OscillationFollowsItsSine) {
    Scene scene = load(makeScene(
        json{{"oscillate", {{"amplitude", {0, 0, 2}}, {"period_s", 4}, {"phase", 0.25}}}}));
    // Phase a quarter period: already at +amplitude on load (t = 0).
    expectNear(glm::vec3(scene.instances[0].worldFromObject[3]), glm::vec3(3, 0, 2));
    scene.update(2.0); // three quarters: -amplitude
    expectNear(glm::vec3(scene.instances[0].worldFromObject[3]), glm::vec3(3, 0, -2));
}

TEST(AnimationTest, UpdateIsDeterministic) {
    const json doc =
        makeScene(json{{"translate_per_s", {0.1, 0, 0}},
                       {"rotate_deg_per_s", {10, 20, 30}},
                       {"orbit", {{"centre", {0, 0, 0}}, {"period_s", 3}}},
                       {"oscillate", {{"amplitude", {0, 1, 0}}, {"period_s", 2}}}},
                  json{{"rotate_deg_per_s", {0, 45, 0}}}, json{{"orbit", {{"period_s", 10}}}});
    Scene a = load(doc);
    Scene b = load(doc);
    a.update(12.345);
    b.update(99.0); // another time first: the result depends on t alone
    b.update(12.345);
    EXPECT_EQ(a.instances[0].worldFromObject, b.instances[0].worldFromObject);
    for (size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].position, b.lights[i].position);
        EXPECT_EQ(a.lights[i].direction, b.lights[i].direction);
    }
}

TEST(AnimationTest, SpotDirectionTurnsAndSunSweeps) {
    Scene scene = load(makeScene(nullptr, json{{"rotate_deg_per_s", {0, 45, 0}}},
                                 json{{"orbit", {{"axis", {0, 1, 0}}, {"period_s", 8}}}}));
    scene.update(2.0); // spot: 90 degrees about +y in place; sun: a quarter turn about +y
    expectNear(scene.lights[0].position, glm::vec3(0, 2, 0));
    expectNear(scene.lights[0].direction, glm::vec3(0, 0, -1));
    expectNear(scene.lights[1].direction, glm::normalize(glm::vec3(0, -1, -1)));
}

TEST(AnimationTest, LightOrbitMovesPosition) {
    json doc = makeScene(nullptr);
    doc["lights"][0] = json::parse(R"({"type": "point", "position": [2, 3, 0],
        "intensity": [1, 1, 1], "animation": {"orbit": {"centre": [0, 0, 0], "period_s": 4}}})");
    Scene scene = load(doc);
    scene.update(1.0); // a quarter turn about +y: +x goes to -z
    expectNear(scene.lights[0].position, glm::vec3(0, 3, -2));
}

TEST(AnimationTest, GeneratorInstancesMoveTogether) {
    json doc = makeScene(nullptr);
    doc["objects"].push_back(
        {{"type", "cornell_box"}, {"animation", {{"translate_per_s", {1, 0, 0}}}}});
    Scene scene = load(doc);
    const size_t cornellInstances = scene.instances.size() - 1;
    ASSERT_EQ(scene.instanceAnimations.size(), cornellInstances);
    scene.update(1.0);
    for (const InstanceAnimation& a : scene.instanceAnimations) {
        const glm::mat4& m = scene.instances[a.instanceIndex].worldFromObject;
        expectNear(glm::vec3(m[3]), glm::vec3(1, 0, 0));
    }
}

struct ErrorCase {
    const char* name;
    json doc;
    std::vector<std::string> expected; // substrings besides the file name
};

TEST(AnimationTest, ErrorsNameFileAndPath) {
    json pointDoc = makeScene(nullptr);
    pointDoc["lights"][0] = json::parse(R"({"type": "point", "position": [0, 2, 0],
        "intensity": [1, 1, 1], "animation": {"rotate_deg_per_s": [0, 10, 0]}})");
    const std::vector<ErrorCase> cases = {
        {"unknown key",
         makeScene(json{{"spin", 1}}),
         {"/objects/0/animation/spin", "unknown key 'spin'"}},
        {"not an object", makeScene(json{1, 2, 3}), {"/objects/0/animation", "JSON object"}},
        {"empty", makeScene(json::object()), {"/objects/0/animation", "at least one motion"}},
        {"wrong type",
         makeScene(json{{"translate_per_s", "fast"}}),
         {"/objects/0/animation/translate_per_s", "3 numbers"}},
        {"zero period",
         makeScene(json{{"orbit", {{"centre", {0, 0, 0}}, {"period_s", 0}}}}),
         {"/objects/0/animation/orbit/period_s", ">= 1e-06, got 0"}},
        {"negative period",
         makeScene(json{{"oscillate", {{"amplitude", {1, 0, 0}}, {"period_s", -2}}}}),
         {"/objects/0/animation/oscillate/period_s", ">= 1e-06, got -2"}},
        {"missing period",
         makeScene(json{{"orbit", {{"centre", {0, 0, 0}}}}}),
         {"/objects/0/animation/orbit/period_s", "required"}},
        {"missing centre",
         makeScene(json{{"orbit", {{"period_s", 1}}}}),
         {"/objects/0/animation/orbit/centre", "required"}},
        {"zero axis",
         makeScene(json{{"orbit", {{"centre", {0, 0, 0}}, {"axis", {0, 0, 0}}, {"period_s", 1}}}}),
         {"/objects/0/animation/orbit/axis", "non-zero"}},
        {"phase in degrees",
         makeScene(json{{"oscillate", {{"amplitude", {1, 0, 0}}, {"period_s", 1}, {"phase", 90}}}}),
         {"/objects/0/animation/oscillate/phase", "[0, 1]"}},
        {"pivot alone",
         makeScene(json{{"pivot", {0, 0, 0}}}),
         {"/objects/0/animation/pivot", "rotate_deg_per_s"}},
        {"sun translated",
         makeScene(nullptr, nullptr, json{{"translate_per_s", {1, 0, 0}}}),
         {"/lights/1/animation/translate_per_s", "only its direction"}},
        {"sun orbit centre",
         makeScene(nullptr, nullptr, json{{"orbit", {{"centre", {0, 0, 0}}, {"period_s", 1}}}}),
         {"/lights/1/animation/orbit/centre", "unknown key"}},
        {"spot bad rate",
         makeScene(nullptr, json{{"rotate_deg_per_s", {0, "x", 0}}}),
         {"/lights/0/animation/rotate_deg_per_s/1", "a number in"}},
        {"point turned in place", pointDoc, {"/lights/0/animation/pivot", "point light"}},
    };
    ScratchDir dir;
    for (const ErrorCase& c : cases) {
        const std::string message = getLoadError(dir, c.doc.dump(2), "anim_bad.json");
        EXPECT_TRUE(contains(message, "anim_bad.json: ")) << c.name << ": " << message;
        for (const std::string& part : c.expected) {
            EXPECT_TRUE(contains(message, part))
                << c.name << ": '" << message << "' lacks '" << part << "'";
        }
        EXPECT_EQ(message.find('\n'), std::string::npos) << c.name;
    }
}

TEST(AnimationTest, DynamicSceneAssetLoadsAndMoves) {
    Scene scene = loadScene(std::string(ISPM_ASSET_DIR) + "/scenes/dynamic.json");
    ASSERT_TRUE(scene.isAnimated());
    const Scene start = scene;
    scene.update(3.0);
    size_t moved = 0;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        moved += scene.instances[i].worldFromObject != start.instances[i].worldFromObject ? 1 : 0;
    }
    EXPECT_EQ(moved, 3u); // orbiting box, spinning pillar, sliding block
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        EXPECT_NE(scene.lights[i].direction, start.lights[i].direction) << i;
    }
}

// ---------------------------------------------------------------------------------------------
// Camera paths.

std::vector<CameraKey> makeKeys() {
    return {{0.0, {0, 1, -10}, {0, 1, 0}, 50.0f},
            {2.0, {4, 1, -6}, {0, 1, 2}, 60.0f},
            {3.0, {4, 2, -2}, {1, 0, 2}, 40.0f},
            {7.0, {0, 1, 0}, {0, 1, 5}, 50.0f}};
}

TEST(CameraPath, PassesThroughItsKeysAndRestsBeyondThem) {
    const auto keys = makeKeys();
    for (const CameraKey& k : keys) {
        const CameraPose p = evaluateCameraPath(keys, k.timeS);
        EXPECT_EQ(p.position, k.position);
        EXPECT_EQ(p.target, k.target);
        EXPECT_EQ(p.fovYDeg, k.fovYDeg);
    }
    EXPECT_EQ(evaluateCameraPath(keys, -1.0).position, keys.front().position);
    EXPECT_EQ(evaluateCameraPath(keys, 100.0).target, keys.back().target);
}

TEST(CameraPath, MovesSmoothlyThroughEachKey) {
    // C1: the velocity just before a key equals the velocity just after it (finite differences
    // of 1e-3 s; their error is O(h) times the spline's second derivative, a few m/s^2 here).
    const auto keys = makeKeys();
    constexpr double kH = 1e-3;
    constexpr float kVelocityTolerance = 0.02f; // m/s, against speeds of 1-4 m/s
    for (size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].timeS;
        const glm::vec3 before =
            (evaluateCameraPath(keys, t).position - evaluateCameraPath(keys, t - kH).position) /
            float(kH);
        const glm::vec3 after =
            (evaluateCameraPath(keys, t + kH).position - evaluateCameraPath(keys, t).position) /
            float(kH);
        EXPECT_LT(glm::length(after - before), kVelocityTolerance) << "key " << i;
        EXPECT_GT(glm::length(after), 0.5f) << "key " << i << ": the camera does not stop";
    }
    // Between keys, no jump: 1 ms moves the camera by at most a few mm.
    for (double t = 0.0; t < 7.0; t += 0.01) {
        const float step = glm::length(evaluateCameraPath(keys, t + kH).position -
                                       evaluateCameraPath(keys, t).position);
        EXPECT_LT(step, 0.02f) << "t " << t;
    }
}

TEST(CameraPath, EvenlySpacedKeysOnALineGiveUniformMotion) {
    // Catmull-Rom reproduces a straight line walked at constant speed exactly.
    const std::vector<CameraKey> keys = {{0.0, {0, 0, 0}, {0, 0, 5}, 45.0f},
                                         {1.0, {1, 0, 0}, {1, 0, 5}, 45.0f},
                                         {2.0, {2, 0, 0}, {2, 0, 5}, 45.0f},
                                         {3.0, {3, 0, 0}, {3, 0, 5}, 45.0f}};
    for (double t = 0.0; t <= 3.0; t += 0.125) {
        const CameraPose p = evaluateCameraPath(keys, t);
        EXPECT_NEAR(p.position.x, t, kTolerance) << t;
        EXPECT_NEAR(p.target.x, t, kTolerance) << t;
        EXPECT_FLOAT_EQ(p.fovYDeg, 45.0f);
    }
}

TEST(CameraPath, FieldOfViewStaysBetweenItsKeys) {
    const auto keys = makeKeys();
    for (double t = 0.0; t <= 7.0; t += 0.05) {
        const CameraPose p = evaluateCameraPath(keys, t);
        EXPECT_GE(p.fovYDeg, 40.0f) << t;
        EXPECT_LE(p.fovYDeg, 60.0f) << t;
    }
}

TEST(CameraPath, AViewThatWouldCollapseKeepsAKeysDirection) {
    // Position and target swap places: half-way both are at the middle.
    const std::vector<CameraKey> keys = {{0.0, {0, 0, 0}, {0, 0, 2}, 45.0f},
                                         {1.0, {0, 0, 2}, {0, 0, 0}, 45.0f}};
    const CameraPose p = evaluateCameraPath(keys, 0.5);
    EXPECT_GT(glm::length(p.target - p.position), 1.0f);
}

TEST(CameraPath, SceneFilesAnimateTheCamera) {
    json doc = makeScene(nullptr);
    doc["camera"] = json::parse(R"({"fov_y_deg": 30, "path": [
        {"time_s": 0, "position": [0, 1, -5], "target": [0, 0, 0]},
        {"time_s": 2, "position": [0, 1, -3], "target": [0, 0, 0], "fov_y_deg": 60}]})");
    Scene scene = load(doc);
    EXPECT_TRUE(scene.isAnimated());
    EXPECT_EQ(scene.camera.position, glm::vec3(0, 1, -5)); // loaded at t = 0
    EXPECT_FLOAT_EQ(scene.camera.fovYDeg, 30.0f);          // the camera's, for keys without one
    scene.update(2.0);
    EXPECT_EQ(scene.camera.position, glm::vec3(0, 1, -3));
    EXPECT_FLOAT_EQ(scene.camera.fovYDeg, 60.0f);
    scene.update(1.0);
    EXPECT_GT(scene.camera.position.z, -5.0f);
    EXPECT_LT(scene.camera.position.z, -3.0f);
}

} // namespace
} // namespace ispm::test
