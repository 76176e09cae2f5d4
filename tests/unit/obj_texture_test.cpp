// OBJ map_Kd textures: read with their vt coordinates (v flipped to the scene's downward v),
// errors for a missing image or missing coordinates, and export that writes them back out
// (glTF textures included) so a textured scene survives the round trip.
#include "scene/obj_io.h"
#include "scene_test_util.h"
#include "support/gltf_scenes.h"

#include <stb_image_write.h>

#include <array>
#include <fstream>
#include <sstream>

namespace ispm::test {
namespace {

// A unit quad (two triangles) whose corners take vt (0,0) (1,0) (1,1) (0,1), textured.
constexpr const char* kTexturedObj = R"(mtllib t.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0.25 0.75
usemtl tex
f 1/1 2/2 3/3
f 1/1 3/3 4/4
)";

// 2 x 2 texels: red, green on the top row; blue, white below.
void writeTinyPng(const std::string& path) {
    const std::array<uint8_t, 16> rgba = {255, 0, 0,   255, 0,   255, 0,   255,
                                          0,   0, 255, 255, 255, 255, 255, 255};
    ASSERT_NE(stbi_write_png(path.c_str(), 2, 2, 4, rgba.data(), 2 * 4), 0);
}

std::string makeScene() {
    return R"({"camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
               "objects": [{"type": "mesh", "obj": "t.obj"}]})";
}

TEST(ObjTexture, MapKdIsReadWithFlippedTexcoords) {
    ScratchDir dir;
    dir.write("t.obj", kTexturedObj);
    dir.write("t.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd tiny.png\n");
    writeTinyPng(dir.getPath("tiny.png"));
    const Scene scene = loadScene(dir.write("s.json", makeScene()));
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].width, 2);
    EXPECT_EQ(scene.textures[0].rgba[4 + 1], 255); // texel (1, 0): green
    const Mesh& mesh = scene.meshes.at(0);
    ASSERT_EQ(mesh.texcoords.size(), mesh.positions.size());
    EXPECT_EQ(scene.materials.at(mesh.triangleMaterials[0]).diffuseTexture, 0u);
    // Vertex 4 (0, 1, 0) carries vt (0.25, 0.75): v runs down in the scene, so 0.25.
    bool found = false;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        if (mesh.positions[i] == glm::vec3(0, 1, 0)) {
            EXPECT_FLOAT_EQ(mesh.texcoords[i].x, 0.25f);
            EXPECT_FLOAT_EQ(mesh.texcoords[i].y, 0.25f);
            found = true;
        }
    }
    EXPECT_TRUE(found);
}

TEST(ObjTexture, MissingImageOrCoordinatesAreErrors) {
    ScratchDir dir;
    dir.write("t.obj", kTexturedObj);
    dir.write("t.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd nowhere.png\n");
    const std::string missing = getLoadError(dir, makeScene());
    EXPECT_TRUE(contains(missing, "/objects/0/obj: expected a valid OBJ file")) << missing;
    EXPECT_TRUE(contains(missing, "map_Kd")) << missing;
    EXPECT_TRUE(contains(missing, "nowhere.png")) << missing;

    writeTinyPng(dir.getPath("tiny.png"));
    dir.write("t.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd tiny.png\n");
    dir.write("t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl tex\nf 1 2 3\n");
    const std::string noVt = getLoadError(dir, makeScene());
    EXPECT_TRUE(contains(noVt, "needs vt coordinates")) << noVt;
}

// map_d naming the map_Kd image cuts the surface out where its alpha is below 0.5 (glTF's MASK
// default); `d` and a map_d of another image are not read. Export writes the map_d back.
TEST(ObjTexture, MapDOfTheColourImageIsAnAlphaTest) {
    ScratchDir dir;
    dir.write("t.obj", kTexturedObj);
    writeTinyPng(dir.getPath("tiny.png"));
    writeTinyPng(dir.getPath("other.png"));
    const auto readCutoff = [&](const std::string& mtl) {
        dir.write("t.mtl", mtl);
        const Scene scene = loadScene(dir.write("s.json", makeScene()));
        return scene.materials.at(scene.meshes.at(0).triangleMaterials[0]).alphaCutoff;
    };
    EXPECT_EQ(readCutoff("newmtl tex\nKd 1 1 1\nmap_Kd tiny.png\nmap_d tiny.png\n"), 0.5f);
    EXPECT_EQ(readCutoff("newmtl tex\nKd 1 1 1\nmap_Kd tiny.png\nmap_d other.png\n"), 0.0f);
    EXPECT_EQ(readCutoff("newmtl tex\nKd 1 1 1\nmap_Kd tiny.png\nd 0.3\n"), 0.0f);

    const Scene scene = loadScene(dir.write("s.json", makeScene()));
    Scene masked = scene;
    masked.materials.at(0).alphaCutoff = 0.5f;
    exportObj(masked, dir.getPath("out.obj"));
    EXPECT_EQ(importObj(dir.getPath("out.obj")).materials.at(0).alphaCutoff, 0.5f);
}

TEST(ObjTexture, ExportWritesTexturesAndCoordinates) {
    ScratchDir dir;
    writeCheckerRoomGltf(dir.getPath("room.gltf"), CheckerRoom{});
    const Scene scene = loadScene(dir.getPath("room.gltf"));
    const std::string objPath = dir.getPath("out.obj");
    exportObj(scene, objPath);
    std::ifstream mtl(dir.getPath("out.mtl"));
    std::stringstream mtlText;
    mtlText << mtl.rdbuf();
    EXPECT_TRUE(contains(mtlText.str(), "map_Kd out_texture0.png")) << mtlText.str();
    // Read back: the same texture, the same coordinates on the floor's corners.
    const ObjModel back = importObj(objPath);
    ASSERT_EQ(back.textures.size(), 1u);
    EXPECT_EQ(back.textures[0].rgba, scene.textures[0].rgba);
    ASSERT_FALSE(back.mesh.texcoords.empty());
    const Mesh& floor = scene.meshes[0];
    for (size_t i = 0; i < floor.positions.size(); ++i) {
        size_t matches = 0;
        for (size_t j = 0; j < back.mesh.positions.size(); ++j) {
            if (back.mesh.positions[j] == floor.positions[i] &&
                back.mesh.texcoords[j] == floor.texcoords[i]) {
                ++matches;
            }
        }
        EXPECT_GE(matches, 1u) << "floor corner " << i;
    }
}

} // namespace
} // namespace ispm::test
