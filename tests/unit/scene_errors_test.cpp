// Malformed scene files: each one must throw InputError whose single-line message names the file
// and the JSON path of the mistake. Every case starts from a valid scene and breaks one thing.
#include "scene_test_util.h"

#include "image/image_io.h"

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace ispm::test {
namespace {

using nlohmann::json;

constexpr const char* kFileName = "bad_scene.json";

json makeValidScene() {
    return json::parse(R"({
        "camera": {"position": [0, 1, -3], "target": [0, 1, 0], "fov_y_deg": 50},
        "materials": {"white": {"diffuse": [0.8, 0.8, 0.8]}},
        "objects": [
            {"type": "mesh", "material": "white",
             "triangles": [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]}
        ],
        "lights": [{"type": "point", "position": [0, 2, 0], "intensity": [10, 10, 10]}]
    })");
}

struct ErrorCase {
    std::string name;
    std::function<std::string()> makeText;
    std::vector<std::string> expected; // substrings of the message besides the file name
};

// The valid scene with one change to its JSON value.
std::function<std::string()> mutate(std::function<void(json&)> change) {
    return [change = std::move(change)] {
        json doc = makeValidScene();
        change(doc);
        return doc.dump(2);
    };
}

// The valid scene with one change, then `from` replaced by `to` in the text: for what a JSON
// value cannot hold (1e999, duplicate keys, syntax errors).
std::function<std::string()> mutateText(std::function<void(json&)> change, std::string from,
                                        std::string to) {
    return [change = std::move(change), from = std::move(from), to = std::move(to)] {
        json doc = makeValidScene();
        change(doc);
        std::string text = doc.dump();
        const size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from << " not in " << text;
        if (at != std::string::npos) text.replace(at, from.size(), to);
        return text;
    };
}

void noChange(json&) {}

json makeBoxCity(const char* key, json value) {
    json city = {{"type", "box_city"}};
    city[key] = std::move(value);
    return city;
}

std::vector<ErrorCase> getErrorCases() {
    return {
        {"BadJsonSyntax",
         mutateText(noChange, "\"camera\":{", "\"camera\":{,"),
         {"line 1, column", "valid JSON"}},
        {"EmptyFile", [] { return std::string(); }, {"valid JSON"}},
        {"TopLevelNotObject", [] { return std::string("[1, 2]"); }, {"a scene"}},
        {"UnknownTopLevelKey", mutate([](json& d) { d["views"] = 1; }), {"/views", "'views'"}},
        {"UnknownCameraKey",
         mutate([](json& d) {
             d["camera"]["positon"] = {0, 0, 0};
         }),
         {"/camera/positon", "'positon'"}},
        {"UnknownMaterialKey",
         mutate([](json& d) { d["materials"]["white"]["albedo"] = 1; }),
         {"/materials/white/albedo"}},
        {"UnknownObjectKey",
         mutate([](json& d) { d["objects"][0]["colour"] = 1; }),
         {"/objects/0/colour"}},
        {"UnknownLightKey",
         mutate([](json& d) { d["lights"][0]["radius"] = 1; }),
         {"/lights/0/radius"}},
        {"KeyOfAnotherLightType",
         mutate([](json& d) {
             d["lights"][0]["irradiance"] = {1, 1, 1};
         }),
         {"/lights/0/irradiance"}},
        {"UnknownLightType",
         mutate([](json& d) { d["lights"][0]["type"] = "laser"; }),
         {"/lights/0/type", "laser"}},
        {"NegativeEnvironmentRadiance",
         mutate([](json& d) {
             d["environment"] = {{"type", "constant"}, {"radiance", {1, -1, 1}}};
         }),
         {"/environment/radiance/1", "-1"}},
        {"SkyWithoutSun",
         mutate([](json& d) {
             d["environment"] = {{"type", "sky"}};
         }),
         {"/environment", "sun_direction"}},
        {"AreaLightWithRadianceAndPower",
         mutate([](json& d) {
             d["lights"][0] = {{"type", "area"}, {"position", {0, 1, 0}}, {"normal", {0, -1, 0}},
                               {"size", {1, 1}}, {"radiance", {1, 1, 1}}, {"power", {1, 1, 1}}};
         }),
         {"/lights/0", "one of radiance"}},
        {"NanEmission",
         mutate([](json& d) {
             d["materials"]["white"]["emission"] = {1, "nan", 1};
         }),
         {"/materials/white/emission/1"}},
        {"UnknownObjectType",
         mutate([](json& d) { d["objects"][0]["type"] = "sphere"; }),
         {"/objects/0/type", "sphere"}},
        {"StringForNumber",
         mutate([](json& d) { d["camera"]["fov_y_deg"] = "wide"; }),
         {"/camera/fov_y_deg", "expected a number"}},
        {"NegativeFov",
         mutate([](json& d) { d["camera"]["fov_y_deg"] = -10; }),
         {"/camera/fov_y_deg", "(0, 180)"}},
        {"FovOf180",
         mutate([](json& d) { d["camera"]["fov_y_deg"] = 180; }),
         {"/camera/fov_y_deg"}},
        {"HugeExponentNumber",
         mutateText([](json& d) { d["camera"]["fov_y_deg"] = 12345.5; }, "12345.5", "1e999"),
         {"/camera/fov_y_deg", "finite"}},
        {"HugeExponentInArray",
         mutateText(
             [](json& d) {
                 d["camera"]["position"] = {0, 12345.5, -3};
             },
             "12345.5", "-1e999"),
         {"/camera/position/1", "finite"}},
        {"BeyondFloatRange",
         mutate([](json& d) {
             d["lights"][0]["intensity"] = {1e39, 1, 1};
         }),
         {"/lights/0/intensity/0"}},
        {"DuplicateKey",
         mutateText(noChange, "\"fov_y_deg\":50", "\"fov_y_deg\":50,\"fov_y_deg\":60"),
         {"/camera/fov_y_deg", "twice"}},
        {"MissingCamera", mutate([](json& d) { d.erase("camera"); }), {"/camera"}},
        {"MissingCameraTarget",
         mutate([](json& d) { d["camera"].erase("target"); }),
         {"/camera/target", "required"}},
        {"CameraPathOneKey",
         mutate([](json& d) {
             d["camera"] = {
                 {"path", {{{"time_s", 0}, {"position", {0, 1, -3}}, {"target", {0, 1, 0}}}}}};
         }),
         {"/camera/path", "two keys"}},
        {"CameraPathTimesGoBack",
         mutate([](json& d) {
             d["camera"] = {{"path",
                             {{{"time_s", 2}, {"position", {0, 1, -3}}, {"target", {0, 1, 0}}},
                              {{"time_s", 1}, {"position", {0, 1, -2}}, {"target", {0, 1, 0}}}}}};
         }),
         {"/camera/path/1/time_s", "after the previous key"}},
        {"CameraPathBesidePosition",
         mutate([](json& d) {
             d["camera"]["path"] = {
                 {{"time_s", 0}, {"position", {0, 1, -3}}, {"target", {0, 1, 0}}},
                 {{"time_s", 1}, {"position", {0, 1, -2}}, {"target", {0, 1, 0}}}};
         }),
         {"/camera/position", "beside a path"}},
        {"CameraPathKeyWithoutTarget",
         mutate([](json& d) {
             d["camera"] = {{"path",
                             {{{"time_s", 0}, {"position", {0, 1, -3}}, {"target", {0, 1, 0}}},
                              {{"time_s", 1}, {"position", {0, 1, -2}}}}}};
         }),
         {"/camera/path/1/target", "required"}},
        {"CameraPathKeyLooksAlongUp",
         mutate([](json& d) {
             d["camera"] = {{"path",
                             {{{"time_s", 0}, {"position", {0, 1, -3}}, {"target", {0, 1, 0}}},
                              {{"time_s", 1}, {"position", {0, 1, 0}}, {"target", {0, 3, 0}}}}}};
         }),
         {"/camera/path/1/up"}},
        {"CameraPathNegativeTime",
         mutate([](json& d) {
             d["camera"] = {{"path",
                             {{{"time_s", -1}, {"position", {0, 1, -3}}, {"target", {0, 1, 0}}},
                              {{"time_s", 1}, {"position", {0, 1, -2}}, {"target", {0, 1, 0}}}}}};
         }),
         {"/camera/path/0/time_s"}},
        {"TargetAtPosition",
         mutate([](json& d) {
             d["camera"]["target"] = {0, 1, -3};
         }),
         {"/camera/target"}},
        {"UpAlongView",
         mutate([](json& d) {
             d["camera"]["up"] = {0, 0, 2};
         }),
         {"/camera/up"}},
        {"LookingDownWithDefaultUp",
         mutate([](json& d) {
             d["camera"]["target"] = {0, -5, -3};
         }),
         {"/camera/up", "default"}},
        {"FarBeforeNear",
         mutate([](json& d) {
             d["camera"]["near"] = 1.0;
             d["camera"]["far"] = 0.5;
         }),
         {"/camera/far"}},
        {"MissingObjects", mutate([](json& d) { d.erase("objects"); }), {"/objects"}},
        {"NoObjects",
         mutate([](json& d) { d["objects"] = json::array(); }),
         {"/objects", "at least one object"}},
        {"EmptyTriangles",
         mutate([](json& d) { d["objects"][0]["triangles"] = json::array(); }),
         {"/objects/0/triangles", "at least one triangle"}},
        {"DegenerateTriangle",
         mutate([](json& d) {
             d["objects"][0]["triangles"].push_back({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
         }),
         {"/objects/0/triangles/1", "non-zero area"}},
        {"TriangleWithTwoPoints",
         mutate([](json& d) { d["objects"][0]["triangles"][0].erase(2); }),
         {"/objects/0/triangles/0", "3 points"}},
        {"TrianglesAndQuads",
         mutate([](json& d) {
             d["objects"][0]["quads"] = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
         }),
         {"/objects/0", "exactly one"}},
        {"MissingObj",
         mutate([](json& d) {
             d["objects"][0].erase("triangles");
             d["objects"][0]["obj"] = "missing_model.obj";
         }),
         {"/objects/0/obj", "missing_model.obj"}},
        {"UnknownMaterial",
         mutate([](json& d) { d["objects"][0]["material"] = "gold"; }),
         {"/objects/0/material", "'gold'"}},
        {"MissingMaterial",
         mutate([](json& d) { d["objects"][0].erase("material"); }),
         {"/objects/0/material"}},
        {"MaterialNumber",
         mutate([](json& d) { d["objects"][0]["material"] = 3; }),
         {"/objects/0/material"}},
        {"ReflectanceAboveOne",
         mutate([](json& d) {
             d["materials"]["white"]["diffuse"] = {1.2, 0.5, 0.5};
         }),
         {"/materials/white/diffuse/0", "[0, 1]"}},
        {"EnergyNotConserved",
         mutate([](json& d) {
             d["materials"]["white"]["specular"] = {0.5, 0.1, 0.1};
         }),
         {"/materials/white", "energy"}},
        {"InlineEnergyNotConserved",
         mutate([](json& d) {
             d["objects"][0]["material"] = {{"diffuse", {0.5, 0.5, 0.5}},
                                            {"transmissive", {0.6, 0.1, 0.1}}};
         }),
         {"/objects/0/material", "energy"}},
        {"IorBelowOne",
         mutate([](json& d) { d["materials"]["white"]["ior"] = 0.5; }),
         {"/materials/white/ior", ">= 1"}},
        {"NegativePhong",
         mutate([](json& d) { d["materials"]["white"]["phong_exponent"] = -1; }),
         {"/materials/white/phong_exponent"}},
        {"NegativeEmission",
         mutate([](json& d) {
             d["materials"]["white"]["emission"] = {1, -1, 1};
         }),
         {"/materials/white/emission/1"}},
        {"MatrixAndTranslate",
         mutate([](json& d) {
             d["objects"][0]["matrix"] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
             d["objects"][0]["translate"] = {1, 2, 3};
         }),
         {"/objects/0/matrix", "not both"}},
        {"ProjectiveMatrix",
         mutate([](json& d) {
             d["objects"][0]["matrix"] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 1, 0}};
         }),
         {"/objects/0/matrix", "affine"}},
        {"SingularMatrix",
         mutate([](json& d) {
             d["objects"][0]["matrix"] = {{1, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
         }),
         {"/objects/0/matrix", "invertible"}},
        {"MatrixWrongShape",
         mutate([](json& d) {
             d["objects"][0]["matrix"] = {1, 2, 3};
         }),
         {"/objects/0/matrix", "4x4"}},
        {"ZeroScale",
         mutate([](json& d) { d["objects"][0]["scale"] = 0; }),
         {"/objects/0/scale", "[1e-06, 1000000]"}},
        {"BoxMaxBelowMin",
         mutate([](json& d) {
             d["objects"][0] = {
                 {"type", "box"}, {"material", "white"}, {"min", {0, 0, 0}}, {"max", {1, 0, 1}}};
         }),
         {"/objects/0/max"}},
        {"IntensityTwoNumbers",
         mutate([](json& d) {
             d["lights"][0]["intensity"] = {1, 2};
         }),
         {"/lights/0/intensity", "3 numbers"}},
        {"NegativeIntensity",
         mutate([](json& d) {
             d["lights"][0]["intensity"] = {1, -2, 1};
         }),
         {"/lights/0/intensity/1", "[0, 1e+12]"}},
        {"SpotTooWide",
         mutate([](json& d) {
             d["lights"][0] = {{"type", "spot"},          {"position", {0, 2, 0}},
                               {"direction", {0, -1, 0}}, {"intensity", {1, 1, 1}},
                               {"inner_deg", 10},         {"outer_deg", 90}};
         }),
         {"/lights/0/outer_deg", "89.9"}},
        {"SpotInnerAboveOuter",
         mutate([](json& d) {
             d["lights"][0] = {{"type", "spot"},          {"position", {0, 2, 0}},
                               {"direction", {0, -1, 0}}, {"intensity", {1, 1, 1}},
                               {"inner_deg", 40},         {"outer_deg", 30}};
         }),
         {"/lights/0/inner_deg"}},
        {"SpotZeroDirection",
         mutate([](json& d) {
             d["lights"][0] = {{"type", "spot"},         {"position", {0, 2, 0}},
                               {"direction", {0, 0, 0}}, {"intensity", {1, 1, 1}},
                               {"inner_deg", 10},        {"outer_deg", 30}};
         }),
         {"/lights/0/direction", "non-zero"}},
        {"SunMissingIrradiance",
         mutate([](json& d) {
             d["lights"][0] = {{"type", "sun"}, {"direction", {0, -1, 0}}};
         }),
         {"/lights/0/irradiance"}},
        {"NegativePhotonShare",
         mutate([](json& d) { d["lights"][0]["photon_share"] = -1; }),
         {"/lights/0/photon_share"}},
        {"UnknownSetting",
         mutate([](json& d) {
             d["render"] = {{"bogus", 1}};
         }),
         {"/render/bogus", "bogus"}},
        {"SettingOutOfRange",
         mutate([](json& d) {
             d["render"] = {{"width", 0}};
         }),
         {"/render/width"}},
        {"SettingBadChoice",
         mutate([](json& d) {
             d["render"] = {{"tonemap", "sepia"}};
         }),
         {"/render/tonemap", "sepia"}},
        {"SettingBoolean",
         mutate([](json& d) {
             d["render"] = {{"gamma", true}};
         }),
         {"/render/gamma"}},
        {"FarTranslate",
         mutate([](json& d) {
             d["objects"][0]["translate"] = {3e38, 0, 0};
         }),
         {"/objects/0/translate/0", "3e+38"}},
        {"TinyScale",
         mutate([](json& d) { d["objects"][0]["scale"] = 1e-38; }),
         {"/objects/0/scale", "1e-06"}},
        {"HugeIntensity",
         mutate([](json& d) {
             d["lights"][0]["intensity"] = {3e38, 3e38, 3e38};
         }),
         {"/lights/0/intensity/0", "1e+12"}},
        {"SettingChoiceAsNumber",
         mutate([](json& d) {
             d["render"] = {{"tonemap", 1}};
         }),
         {"/render/tonemap", "filmic", "not a number"}},
        {"CityHeightRangeReversed",
         mutate([](json& d) {
             d["objects"][0] = makeBoxCity("building_height", {30, 10});
         }),
         {"/objects/0/building_height", "min <= max"}},
        {"CityInsetTooLarge",
         mutate([](json& d) {
             d["objects"][0] = makeBoxCity("building_inset", {1, 20});
         }),
         {"/objects/0/building_inset", "lot size"}},
        {"CityTooManyBuildings",
         mutate([](json& d) {
             d["objects"][0] = makeBoxCity("blocks", {200, 200});
         }),
         {"/objects/0/blocks", "10000"}},
        {"CityTooManyAttachments",
         mutate([](json& d) {
             d["objects"][0] = makeBoxCity("attachments", {0, 17});
         }),
         {"/objects/0/attachments/1"}},
        {"CityAlleysFillBlock",
         mutate([](json& d) { d["objects"][0] = makeBoxCity("alley_width", 50); }),
         {"/objects/0/alley_width"}},
        {"CityNegativeSeed",
         mutate([](json& d) { d["objects"][0] = makeBoxCity("seed", -1); }),
         {"/objects/0/seed"}},
        {"CityUnknownKey",
         mutate([](json& d) { d["objects"][0] = makeBoxCity("towers", 3); }),
         {"/objects/0/towers"}},
        {"CornellWithMaterial",
         mutate([](json& d) {
             d["objects"][0] = {{"type", "cornell_box"}, {"material", "white"}};
         }),
         {"/objects/0/material"}},
    };
}

class SceneErrorTest : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneErrorTest, ThrowsInputErrorNamingFileAndPath) {
    const ErrorCase& c = GetParam();
    ScratchDir dir;
    const std::string message = getLoadError(dir, c.makeText(), kFileName);
    ASSERT_FALSE(message.empty()) << "no InputError";
    EXPECT_TRUE(contains(message, kFileName)) << message;
    for (const std::string& part : c.expected) {
        EXPECT_TRUE(contains(message, part)) << "'" << part << "' not in: " << message;
    }
    EXPECT_FALSE(contains(message, "\n")) << message;
}

std::string getCaseName(const ::testing::TestParamInfo<ErrorCase>& caseInfo) {
    return caseInfo.param.name;
}

INSTANTIATE_TEST_SUITE_P(Malformed, SceneErrorTest, ::testing::ValuesIn(getErrorCases()),
                         getCaseName);

TEST(SceneErrors, ValidBaseSceneLoads) {
    ScratchDir dir;
    EXPECT_EQ(getLoadError(dir, makeValidScene().dump()), "");
}

TEST(SceneErrors, MissingSceneFileIsInputError) {
    ScratchDir dir;
    const std::string path = dir.getPath("nowhere.json");
    try {
        loadScene(path);
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "nowhere.json")) << e.what();
    }
}

TEST(SceneErrors, DeepNestingIsRefusedAsItIsRead) {
    // 100,000 nested arrays (200 KB) took memory quadratic in the depth and crashed.
    constexpr size_t kDepth = 100000;
    ScratchDir dir;
    const std::string text =
        "{\"camera\": " + std::string(kDepth, '[') + std::string(kDepth, ']') + "}";
    const std::string message = getLoadError(dir, text, "deep.json");
    EXPECT_TRUE(contains(message, "deep.json")) << message.substr(0, 200);
    EXPECT_TRUE(contains(message, "levels of nesting")) << message.substr(0, 200);
    EXPECT_LT(message.size(), 400u); // one line, its path cut at the limit
}

TEST(SceneErrors, MessageHasTheDocumentedForm) {
    // "<file>: <JSON path>: expected <what>", as the format document promises.
    ScratchDir dir;
    json doc = makeValidScene();
    doc["lights"][0]["intensity"] = "bright";
    const std::string path = dir.write("form.json", doc.dump());
    try {
        loadScene(path);
        FAIL() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(
            std::string(e.what()).rfind(path + ": /lights/0/intensity: expected 3 numbers", 0), 0u)
            << e.what();
    }
}

// Environment images: the scene names an image file beside it; each broken one (missing,
// corrupt, not 2:1, a negative or NaN texel) or a negative scale is one line naming the scene
// file, the JSON path and the image file.
struct ImageCase {
    const char* name;
    std::function<void(const ScratchDir&)> writeFiles; // the image, sky.pfm
    json environment;
    std::vector<std::string> expected;
};

void writeMap(const ScratchDir& dir, int width, int height, float bad = 1.0f) {
    Image image(width, height, glm::vec3(1.0f));
    image.at(1, 1).g = bad;
    writeImage(dir.getPath("sky.pfm"), image);
}

TEST(SceneErrors, BrokenEnvironmentImages) {
    const json image = {{"image", "sky.pfm"}};
    const std::vector<ImageCase> cases = {
        {"missing", [](const ScratchDir&) {}, image, {"/environment/image", "sky.pfm", "open"}},
        {"corrupt",
         [](const ScratchDir& dir) { dir.write("sky.pfm", "PF\n4 2\n-1.0\nshort"); },
         image,
         {"/environment/image", "sky.pfm"}},
        {"three by two",
         [](const ScratchDir& dir) { writeMap(dir, 6, 4); },
         image,
         {"/environment/image", "sky.pfm", "twice as wide", "6 x 4"}},
        {"negative texel",
         [](const ScratchDir& dir) { writeMap(dir, 8, 4, -0.5f); },
         image,
         {"/environment/image", "sky.pfm", "-0.5", "(1, 1)"}},
        {"NaN texel",
         [](const ScratchDir& dir) {
             writeMap(dir, 8, 4, std::numeric_limits<float>::quiet_NaN());
         },
         image,
         {"/environment/image", "sky.pfm", "nan", "(1, 1)"}},
        {"infinite texel",
         [](const ScratchDir& dir) { writeMap(dir, 8, 4, std::numeric_limits<float>::infinity()); },
         image,
         {"/environment/image", "sky.pfm", "inf"}},
        {"negative scale",
         [](const ScratchDir& dir) { writeMap(dir, 8, 4); },
         {{"image", "sky.pfm"}, {"scale", -1}},
         {"/environment/scale", "-1"}},
        {"not an image type",
         [](const ScratchDir& dir) { writeMap(dir, 8, 4); },
         {{"image", "sky.png"}},
         {"/environment/image", "EXR or PFM"}},
    };
    for (const ImageCase& c : cases) {
        ScratchDir dir;
        c.writeFiles(dir);
        json doc = makeValidScene();
        doc["environment"] = c.environment;
        const std::string message = getLoadError(dir, doc.dump(), kFileName);
        ASSERT_FALSE(message.empty()) << c.name << ": no InputError";
        EXPECT_TRUE(contains(message, kFileName)) << c.name << ": " << message;
        for (const std::string& part : c.expected) {
            EXPECT_TRUE(contains(message, part))
                << c.name << ": '" << part << "' not in: " << message;
        }
        EXPECT_FALSE(contains(message, "\n")) << c.name << ": " << message;
    }
}

TEST(SceneErrors, EnvironmentImageBesideTheSceneLoads) {
    ScratchDir dir;
    writeMap(dir, 8, 4, 3.0f);
    json doc = makeValidScene();
    doc["environment"] = {{"image", "sky.pfm"}, {"rotation_deg", 90}, {"scale", 2}};
    const Scene scene = loadScene(dir.write("scene.json", doc.dump()));
    ASSERT_EQ(scene.environment.type, EnvironmentType::Image);
    EXPECT_EQ(scene.environment.image->width, 8);
    EXPECT_EQ(scene.environment.image->radiance[size_t(1 * 8 + 1)], glm::vec3(2.0f, 6.0f, 2.0f));
    EXPECT_EQ(scene.environment.rotationDeg, 90.0f);
}

} // namespace
} // namespace ispm::test
