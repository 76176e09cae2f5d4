// glTF import: files written by tinygltf (support/gltf_scenes) loaded through loadScene, the
// photometric and material conversions against numbers worked by hand, and malformed files
// rejected with the file and the JSON path of the fault.
#include "scene/gltf_units.h"
#include "scene/scene_texture.h"
#include "scene_test_util.h"
#include "support/gltf_scenes.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <vector>

namespace ispm::test {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

TEST(GltfUnits, CandelaAndLuxDivideByLuminousEfficacy) {
    // 683 lm/W at 555 nm: 683 cd is 1 W/sr, 683 lux is 1 W/m^2.
    EXPECT_FLOAT_EQ(convertCandelaToWattsPerSr(glm::vec3(683.0f)).x, 1.0f);
    EXPECT_FLOAT_EQ(convertLuxToWattsPerM2(glm::vec3(1366.0f)).y, 2.0f);
    // Blender's exporter ("Standard" lighting) writes a P-watt point light as P / (4 pi) * 683
    // cd: the importer gives back P / (4 pi) W/sr, the intensity Blender renders it with.
    const float watts = 1000.0f;
    const float candela = watts / (4.0f * kPi) * 683.0f;
    EXPECT_NEAR(convertCandelaToWattsPerSr(glm::vec3(candela)).z, watts / (4.0f * kPi), 1e-3f);
}

TEST(GltfUnits, RoughnessToPhongExponent) {
    // alpha = r^2; n = (2 / alpha^2 - 2) / 4, at least 1.
    EXPECT_FLOAT_EQ(convertRoughnessToPhongExponent(1.0f), kMinGltfPhongExponent);
    EXPECT_FLOAT_EQ(convertRoughnessToPhongExponent(0.8f), kMinGltfPhongExponent); // 0.72
    EXPECT_FLOAT_EQ(convertRoughnessToPhongExponent(0.5f), 7.5f);                  // alpha^2 = 1/16
    EXPECT_NEAR(convertRoughnessToPhongExponent(0.2f), 312.0f, 0.1f); // alpha^2 = 0.0016
    EXPECT_FLOAT_EQ(convertRoughnessToPhongExponent(0.0f), kMaxGltfPhongExponent);
    // Rougher is never sharper.
    for (float r = 0.05f; r < 1.0f; r += 0.05f) {
        EXPECT_GE(convertRoughnessToPhongExponent(r), convertRoughnessToPhongExponent(r + 0.05f));
    }
}

TEST(GltfUnits, MetallicRoughnessConservesEnergy) {
    const glm::vec3 base(0.8f, 0.4f, 0.1f);
    const Material dielectric = convertMetallicRoughness(base, 0.0f, 0.5f, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(dielectric.diffuse.r, 0.96f * 0.8f);
    EXPECT_FLOAT_EQ(dielectric.specular.g, 0.04f); // colourless coat
    const Material metal = convertMetallicRoughness(base, 1.0f, 0.5f, glm::vec3(0.5f));
    EXPECT_FLOAT_EQ(metal.diffuse.r, 0.0f);
    EXPECT_FLOAT_EQ(metal.specular.r, 0.4f); // base x the texture's mean
    for (float m = 0.0f; m <= 1.0f; m += 0.25f) {
        const Material w = convertMetallicRoughness(glm::vec3(1.0f), m, 0.3f, glm::vec3(1.0f));
        EXPECT_LE(w.diffuse.r + w.specular.r, 1.0f + 1e-6f) << "metallic " << m;
        EXPECT_GE(w.diffuse.r + w.specular.r, 0.999f) << "white loses nothing, metallic " << m;
    }
}

TEST(GltfUnits, SrgbDecode) {
    EXPECT_FLOAT_EQ(decodeSrgb(0), 0.0f);
    EXPECT_FLOAT_EQ(decodeSrgb(255), 1.0f);
    EXPECT_NEAR(decodeSrgb(128), 0.2158f, 1e-4f);                // the standard's table
    EXPECT_NEAR(decodeSrgb(10), 10.0f / 255.0f / 12.92f, 1e-7f); // linear segment
}

TEST(GltfImport, ReadsMeshesTextureLightAndCamera) {
    ScratchDir dir;
    CheckerRoom room;
    room.candela = 1366.0f;
    room.cameraPositionM = {0.1f, 1.5f, 0.2f};
    const std::string path = dir.getPath("room.gltf");
    writeCheckerRoomGltf(path, room);
    const Scene scene = loadScene(path);
    ASSERT_EQ(scene.meshes.size(), 2u); // floor and ceiling
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.countTriangles(), 4u);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].width, room.checks * room.texelsPerCheck);
    // Texel (0, 0) is colour A (red); the next square along u is colour B (white).
    EXPECT_EQ(scene.textures[0].rgba[0], 255);
    EXPECT_EQ(scene.textures[0].rgba[1], 0);
    EXPECT_EQ(scene.textures[0].rgba[4 * room.texelsPerCheck + 1], 255);
    const Mesh& floor = scene.meshes[0];
    ASSERT_EQ(floor.texcoords.size(), floor.positions.size());
    const Material& checker = scene.materials[floor.triangleMaterials[0]];
    EXPECT_EQ(checker.diffuseTexture, 0u);
    EXPECT_FLOAT_EQ(checker.diffuse.g, 0.96f); // white factor, metallic 0
    EXPECT_EQ(scene.materials[scene.meshes[1].triangleMaterials[0]].diffuseTexture, kNoTexture);
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& spot = scene.lights[0];
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_FLOAT_EQ(spot.intensity.r, 2.0f); // 1366 cd / 683 lm/W
    EXPECT_NEAR(spot.direction.y, -1.0f, 1e-6f);
    EXPECT_NEAR(spot.position.y, room.lightHeightM, 1e-6f);
    EXPECT_NEAR(spot.outerDeg, glm::degrees(room.outerConeRad), 1e-4f);
    EXPECT_NEAR(scene.camera.position.x, 0.1f, 1e-6f);
    EXPECT_NEAR(scene.camera.target.y, 0.5f, 1e-5f); // one metre below, looking down
    EXPECT_NEAR(scene.camera.fovYDeg, glm::degrees(room.cameraYFovRad), 1e-4f);
    EXPECT_NEAR(scene.camera.up.z, -1.0f, 1e-6f);
    ASSERT_EQ(scene.namedCameras.size(), 1u);
    EXPECT_EQ(scene.namedCameras[0].first, "eye");
}

TEST(GltfImport, BinaryGlbReadsAsTheTextFile) {
    ScratchDir dir;
    writeCheckerRoomGltf(dir.getPath("room.gltf"), CheckerRoom{});
    writeCheckerRoomGltf(dir.getPath("room.glb"), CheckerRoom{});
    const Scene text = loadScene(dir.getPath("room.gltf"));
    const Scene binary = loadScene(dir.getPath("room.glb"));
    ASSERT_EQ(binary.meshes.size(), text.meshes.size());
    for (size_t i = 0; i < text.meshes.size(); ++i) {
        EXPECT_EQ(binary.meshes[i].positions, text.meshes[i].positions);
        EXPECT_EQ(binary.meshes[i].texcoords, text.meshes[i].texcoords);
        EXPECT_EQ(binary.meshes[i].triangles, text.meshes[i].triangles);
    }
    ASSERT_EQ(binary.textures.size(), 1u);
    EXPECT_EQ(binary.textures[0].rgba, text.textures[0].rgba);
    EXPECT_EQ(binary.lights.size(), 1u);
}

TEST(GltfImport, ObjectInSceneFileIsPlacedByItsTransform) {
    ScratchDir dir;
    writeCheckerRoomGltf(dir.getPath("room.gltf"), CheckerRoom{});
    const Scene scene = loadScene(dir.write("s.json", R"({
        "camera": {"position": [0, 1, 5], "target": [0, 1, 0]},
        "objects": [{"type": "gltf", "path": "room.gltf", "translate": [10, 0, 0]}]})"));
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_FLOAT_EQ(scene.instances[0].worldFromObject[3].x, 10.0f);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_FLOAT_EQ(scene.lights[0].position.x, 10.0f);
    EXPECT_EQ(scene.camera.position.z, 5.0f); // the file's camera; the glTF's is named
    EXPECT_EQ(scene.namedCameras.size(), 1u);
}

// alphaMode and alphaCutoff as Material::alphaCutoff, a bound on the texture's alpha alone: the
// factor's alpha divides glTF's cutoff; BLEND is MASK at 0.5; OPAQUE has none. doubleSided is
// kept as written (every surface is two-sided all the same).
TEST(GltfImport, AlphaModesBecomeCutoffsOnTheTexturesAlpha) {
    ScratchDir dir;
    struct Case {
        const char* mode;
        double cutoff;
        double factorAlpha;
        float expected;
    };
    const Case cases[] = {{"MASK", 0.5, 1.0, 0.5f},   {"MASK", 0.3, 0.5, 0.6f},
                          {"MASK", 0.8, 0.4, 2.0f},   {"BLEND", 0.9, 1.0, 0.5f},
                          {"OPAQUE", 0.7, 0.5, 0.0f}, {"MASK", 0.0, 1.0, 0.0f}};
    for (const Case& c : cases) {
        LeafCard card;
        card.alphaMode = c.mode;
        card.alphaCutoff = c.cutoff;
        card.factorAlpha = c.factorAlpha;
        const std::string path = dir.getPath("leaf.gltf");
        writeLeafCardGltf(path, card);
        const Scene scene = loadScene(path);
        ASSERT_EQ(scene.meshes.size(), 2u);
        const Material& leaf = scene.materials[scene.meshes[1].triangleMaterials[0]];
        const Material& floor = scene.materials[scene.meshes[0].triangleMaterials[0]];
        EXPECT_FLOAT_EQ(leaf.alphaCutoff, c.expected) << c.mode << " " << c.cutoff;
        EXPECT_EQ(floor.alphaCutoff, 0.0f);
        EXPECT_TRUE(leaf.doubleSided);
    }
    // glTF's default is one-sided: read as written.
    writeLeafCardGltf(dir.getPath("leaf.gltf"), LeafCard{});
    std::ifstream in(dir.getPath("leaf.gltf"));
    nlohmann::json doc = nlohmann::json::parse(in);
    doc["materials"][1].erase("doubleSided");
    const Scene oneSided = loadScene(dir.write("one_sided.gltf", doc.dump()));
    EXPECT_FALSE(oneSided.materials[oneSided.meshes[1].triangleMaterials[0]].doubleSided);
}

// The glTF file as JSON, to be broken field by field.
nlohmann::json readRoomJson(const ScratchDir& dir) {
    const std::string path = dir.getPath("room.gltf");
    writeCheckerRoomGltf(path, CheckerRoom{});
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

std::string getGltfError(const ScratchDir& dir, const nlohmann::json& doc) {
    return getLoadError(dir, doc.dump(), "bad.gltf");
}

TEST(GltfImport, MalformedFilesNameFileAndJsonPath) {
    ScratchDir dir;
    const nlohmann::json good = readRoomJson(dir);
    ASSERT_EQ(getGltfError(dir, good), "");

    struct Case {
        const char* what;
        std::function<void(nlohmann::json&)> breakIt;
        const char* path;
    };
    const std::vector<Case> cases = {
        {"position accessor past the end",
         [](nlohmann::json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 99; },
         "/meshes/0/primitives/0/attributes/POSITION"},
        {"base colour above 1",
         [](nlohmann::json& d) {
             d["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 2.0, 1.0, 1.0};
         },
         "/materials/0/pbrMetallicRoughness/baseColorFactor/1"},
        {"base colour's alpha above 1",
         [](nlohmann::json& d) {
             d["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1.0, 1.0, 1.0, 1.5};
         },
         "/materials/0/pbrMetallicRoughness/baseColorFactor/3"},
        {"negative alpha cutoff",
         [](nlohmann::json& d) {
             d["materials"][0]["alphaMode"] = "MASK";
             d["materials"][0]["alphaCutoff"] = -0.5;
         },
         "/materials/0/alphaCutoff"},
        {"unknown alpha mode", [](nlohmann::json& d) { d["materials"][0]["alphaMode"] = "CUTOUT"; },
         "/materials/0/alphaMode"},
        {"accessor longer than its view",
         [](nlohmann::json& d) { d["accessors"][0]["count"] = 1000; }, "/accessors/0"},
        {"index beyond the vertices",
         [](nlohmann::json& d) {
             d["accessors"][2]["bufferView"] = d["accessors"][0]["bufferView"];
             d["accessors"][2]["componentType"] = 5125; // floats read as huge indices
         },
         "/accessors/2"},
        {"unknown light type",
         [](nlohmann::json& d) {
             d["extensions"]["KHR_lights_punctual"]["lights"][0]["type"] = "area";
         },
         "/extensions/KHR_lights_punctual/lights/0/type"},
        {"spot wider than a half space",
         [](nlohmann::json& d) {
             d["extensions"]["KHR_lights_punctual"]["lights"][0]["spot"]["outerConeAngle"] = 2.0;
         },
         "/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle"},
        {"node its own ancestor", [](nlohmann::json& d) { d["nodes"][0]["children"] = {0}; },
         "/nodes/0/children"},
        {"flat node",
         [](nlohmann::json& d) {
             d["nodes"][0]["scale"] = {1.0, 0.0, 1.0};
         },
         "/nodes/0"},
        {"strip primitives", [](nlohmann::json& d) { d["meshes"][0]["primitives"][0]["mode"] = 5; },
         "/meshes/0/primitives/0/mode"},
        {"normal map naming a texture past the end",
         [](nlohmann::json& d) {
             d["materials"][0]["normalTexture"] = {{"index", 5}};
         },
         "/materials/0/normalTexture/index"},
        {"normal map on a texture coordinate set ispm does not read",
         [](nlohmann::json& d) {
             d["materials"][0]["normalTexture"] = {{"index", 0}, {"texCoord", 1}};
         },
         "/materials/0/normalTexture/texCoord"},
        {"normal map scale beyond reason",
         [](nlohmann::json& d) {
             d["materials"][0]["normalTexture"] = {{"index", 0}, {"scale", 1e6}};
         },
         "/materials/0/normalTexture/scale"},
        {"tangents of three components",
         [](nlohmann::json& d) {
             d["materials"][0]["normalTexture"] = {{"index", 0}};
             auto& attributes = d["meshes"][0]["primitives"][0]["attributes"];
             attributes["TANGENT"] = attributes["POSITION"];
         },
         "/accessors/0/type"}, // "... (used at /meshes/0/primitives/0/attributes/TANGENT)"
        {"textured primitive without texture coordinates",
         [](nlohmann::json& d) {
             d["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
         },
         "/meshes/0/primitives/0/attributes"},
    };
    for (const Case& c : cases) {
        nlohmann::json doc = good;
        c.breakIt(doc);
        const std::string error = getGltfError(dir, doc);
        EXPECT_TRUE(contains(error, "bad.gltf: ")) << c.what << ": " << error;
        EXPECT_TRUE(contains(error, std::string(c.path) + ": expected")) << c.what << ": " << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << c.what << ": one line";
    }
    // Not glTF at all: tinygltf's reason, on one line, with the file.
    const std::string notJson = getLoadError(dir, "{ this is not json", "broken.gltf");
    EXPECT_TRUE(contains(notJson, "broken.gltf: expected a valid glTF 2.0 file")) << notJson;
    EXPECT_EQ(notJson.find('\n'), std::string::npos);
    // A scene file's gltf object naming a missing file.
    const std::string missing =
        getLoadError(dir, R"({"camera": {"position": [0, 0, 1], "target": [0, 0, 0]},
                 "objects": [{"type": "gltf", "path": "nowhere.glb"}]})");
    EXPECT_TRUE(contains(missing, "/objects/0/path: expected an existing .gltf or .glb file"))
        << missing;
}

} // namespace
} // namespace ispm::test
