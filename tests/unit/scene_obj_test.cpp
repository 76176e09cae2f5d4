// OBJ import through scene files (materials from MTL, overrides, errors) and OBJ + MTL export of
// whole scenes, generated geometry included.
#include "core/input_error.h"
#include "scene/box_city.h"
#include "scene/obj_io.h"
#include "scene_test_util.h"

#include <fstream>
#include <map>
#include <sstream>

namespace ispm::test {
namespace {

constexpr const char* kObjText = R"(# a quad, a triangle, an unused vertex and a degenerate face
mtllib model.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 5 5 5
v 2 0 0
usemtl red
f 1 2 3 4
usemtl shiny
f 2 6 3
f 1 2 6
)";

constexpr const char* kMtlText = R"(newmtl red
Kd 0.6 0.1 0.1
newmtl shiny
Kd 0.3 0.3 0.3
Ks 0.5 0.5 0.5
Ns 64
)";

std::string makeObjScene(const std::string& objectExtra) {
    return R"({"camera": {"position": [0, 0, -3], "target": [0, 0, 0]},
               "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
               "objects": [{"type": "mesh", "obj": "model.obj")" +
           objectExtra + "}]}";
}

TEST(ObjImport, UsesMtlMaterialsAndDropsDegenerateFaces) {
    ScratchDir dir;
    dir.write("model.obj", kObjText);
    dir.write("model.mtl", kMtlText);
    const Scene scene = loadScene(dir.write("s.json", makeObjScene("")));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.triangles.size(), 3u); // the quad's two and one triangle; (1 2 6) is flat
    EXPECT_EQ(mesh.positions.size(), 5u); // the unused vertex is not kept
    EXPECT_FLOAT_EQ(mesh.computeBounds().hi.x, 2.0f);
    ASSERT_EQ(scene.materials.size(), 3u); // grey, then the two from the MTL
    EXPECT_EQ(scene.materials[1].name, "model.obj:red");
    EXPECT_EQ(scene.materials[2].name, "model.obj:shiny");
    EXPECT_FLOAT_EQ(scene.materials[2].phongExponent, 64.0f);
    EXPECT_EQ(mesh.triangleMaterials, (std::vector<uint32_t>{1, 1, 2}));
}

TEST(ObjImport, ObjectMaterialOverridesTheFile) {
    ScratchDir dir;
    dir.write("model.obj", kObjText); // no MTL file beside it: not needed with an override
    const Scene scene = loadScene(dir.write("s.json", makeObjScene(R"(, "material": "grey")")));
    EXPECT_EQ(scene.materials.size(), 1u);
    for (uint32_t m : scene.meshes[0].triangleMaterials)
        EXPECT_EQ(m, 0u);
}

TEST(ObjImport, FacesWithoutMaterialNeedAnOverride) {
    ScratchDir dir;
    dir.write("model.obj", kObjText); // the MTL is missing
    const std::string message = getLoadError(dir, makeObjScene(""), "s.json");
    EXPECT_TRUE(contains(message, "s.json: /objects/0/obj")) << message;
    EXPECT_TRUE(contains(message, "material")) << message;
}

TEST(ObjImport, MtlMaterialMustConserveEnergy) {
    ScratchDir dir;
    dir.write("model.obj", kObjText);
    dir.write("model.mtl", "newmtl red\nKd 0.9 0.1 0.1\nKs 0.5 0.5 0.5\nnewmtl shiny\n");
    const std::string message = getLoadError(dir, makeObjScene(""), "s.json");
    EXPECT_TRUE(contains(message, "/objects/0/obj")) << message;
    EXPECT_TRUE(contains(message, "'red'")) << message;
}

TEST(ObjImport, MaterialValuesOutOfRangeAreErrors) {
    // Checked as the JSON loader checks its own materials (a negative reflectance or an emission
    // of 1e30 was accepted).
    for (const char* mtl : {"newmtl red\nKd 0.5 -0.1 0.1\nnewmtl shiny\n",
                            "newmtl red\nKd 0.5 0.1 0.1\nKe 1e30 0 0\nnewmtl shiny\n",
                            "newmtl red\nKd 0.5 0.1 0.1\nKs -1 0 0\nnewmtl shiny\n"}) {
        ScratchDir dir;
        dir.write("model.obj", kObjText);
        dir.write("model.mtl", mtl);
        const std::string message = getLoadError(dir, makeObjScene(""), "s.json");
        EXPECT_TRUE(contains(message, "/objects/0/obj")) << message;
        EXPECT_TRUE(contains(message, "'red'")) << message;
    }
}

TEST(ObjImport, NumbersThatDoNotReadWholeAreErrors) {
    // tinyobjloader reads "nan", "inf" and "1.5x" as 0 and wraps face indices past 32 bits; each
    // is refused with its line and token.
    struct Case {
        std::string obj;
        std::string mtl;
        std::string expected;
    };
    const std::string quad = "mtllib model.mtl\nusemtl red\n";
    const std::vector<Case> cases = {
        {quad + "v 0 0 0\nv 1 0 0\nv 0 nan 1\nf 1 2 3\n", kMtlText, "line 5 (v)"},
        {quad + "v 0 0 0\nv 1 0 -inf\nv 0 1 1\nf 1 2 3\n", kMtlText, "'-inf'"},
        {quad + "v 0 0 0\nv 1 0 0\nv 0 1.5x 1\nf 1 2 3\n", kMtlText, "'1.5x'"},
        {quad + "v 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 99999999999\n", kMtlText, "(f)"},
        {quad + "v 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n", "newmtl red\nKd nan 0.5 0.5\n",
         "'model.mtl' line 2 (Kd)"},
        {quad + "v 0 0 0\nv 1 0 0\nv 0 1 1\nf 1 2 3\n", "newmtl red\nKd 0.5 0.5 0.5\nKe inf 0 0\n",
         "'model.mtl' line 3 (Ke)"},
    };
    for (const Case& c : cases) {
        ScratchDir dir;
        dir.write("model.obj", c.obj);
        dir.write("model.mtl", c.mtl);
        const std::string message = getLoadError(dir, makeObjScene(""), "s.json");
        EXPECT_TRUE(contains(message, "s.json: /objects/0/obj")) << message;
        EXPECT_TRUE(contains(message, c.expected)) << message;
    }
    // Signs, exponents and relative indices still read.
    ScratchDir dir;
    dir.write("model.obj", quad + "v +0 0 0\nv 1e0 0 0\nv 0 .5 1\nf -3 -2 -1\n");
    dir.write("model.mtl", kMtlText);
    EXPECT_EQ(loadScene(dir.write("s.json", makeObjScene(""))).meshes[0].triangles.size(), 1u);
}

TEST(ObjImport, FileWithoutFacesIsAnError) {
    ScratchDir dir;
    dir.write("model.obj", "v 0 0 0\nv 1 0 0\n");
    const std::string message =
        getLoadError(dir, makeObjScene(R"(, "material": "grey")"), "s.json");
    EXPECT_TRUE(contains(message, "/objects/0/obj")) << message;
}

std::map<std::string, size_t> countLinesByKeyword(const std::string& path) {
    std::ifstream in(path);
    std::map<std::string, size_t> counts;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        ++counts[keyword];
    }
    return counts;
}

TEST(ObjExport, WritesEveryTriangleInWorldSpace) {
    ScratchDir dir;
    const Scene scene = loadScene(dir.write("s.json", R"({
        "camera": {"position": [0, 50, -300], "target": [0, 0, 0]},
        "materials": {"glass": {"transmissive": [0.9, 0.9, 0.9], "ior": 1.5},
                      "lamp": {"emission": [5, 5, 5]}},
        "objects": [
            {"type": "box_city", "blocks": [2, 2], "seed": 3},
            {"type": "cornell_box", "translate": [0, 10, 0]},
            {"type": "box", "material": "glass", "min": [0, 0, 0], "max": [1, 1, 1],
             "translate": [100, 0, 0]},
            {"type": "mesh", "material": "lamp", "triangles": [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]}
        ]
    })"));
    const std::string objPath = dir.getPath("city.obj");
    exportObj(scene, objPath);

    size_t vertexCount = 0;
    for (const Instance& instance : scene.instances) {
        vertexCount += scene.meshes[instance.meshIndex].positions.size();
    }
    const std::map<std::string, size_t> obj = countLinesByKeyword(objPath);
    EXPECT_EQ(obj.at("v"), vertexCount);
    EXPECT_EQ(obj.at("f"), scene.countTriangles());
    EXPECT_EQ(obj.at("o"), scene.instances.size());
    EXPECT_EQ(obj.at("mtllib"), 1u);

    const std::map<std::string, size_t> mtl = countLinesByKeyword(dir.getPath("city.mtl"));
    EXPECT_EQ(mtl.at("newmtl"), scene.materials.size());
    EXPECT_EQ(mtl.at("Ke"), 1u); // only the lamp emits
    EXPECT_EQ(mtl.at("Tf"), 1u); // only the glass transmits

    // Reading it back gives the same triangles in world space and the same materials.
    const ObjModel back = importObj(objPath);
    EXPECT_EQ(back.mesh.triangles.size(), scene.countTriangles());
    const Aabb world = scene.computeWorldBounds();
    const Aabb read = back.mesh.computeBounds();
    EXPECT_EQ(read.lo, world.lo);
    EXPECT_EQ(read.hi, world.hi);
    ASSERT_EQ(back.materials.size(), scene.materials.size());
    for (size_t i = 0; i < back.materials.size(); ++i) {
        EXPECT_EQ(back.materials[i].diffuse, scene.materials[i].diffuse);
        EXPECT_EQ(back.materials[i].transmissive, scene.materials[i].transmissive);
        EXPECT_EQ(back.materials[i].emission, scene.materials[i].emission);
    }
}

TEST(ObjExport, UnwritablePathThrowsNamingTheFile) {
    Scene scene;
    addBoxCity(scene, BoxCityParams{}, glm::mat4(1.0f));
    try {
        exportObj(scene, "/nonexistent_ispm_dir/out.obj");
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_TRUE(contains(e.what(), "/nonexistent_ispm_dir/out.")) << e.what();
    }
}

TEST(ObjExport, NamesStayApartAndOnlyObjPathsAreTaken) {
    ScratchDir dir;
    Scene scene = loadScene(dir.write("s.json", R"({
        "camera": {"position": [0, 1, -3], "target": [0, 0, 0]},
        "materials": {"red paint": {"diffuse": [0.8, 0.1, 0.1]},
                      "red_paint": {"diffuse": [0.1, 0.1, 0.8]}},
        "objects": [
            {"type": "box", "material": "red paint", "min": [0, 0, 0], "max": [1, 1, 1]},
            {"type": "box", "material": "red_paint", "min": [2, 0, 0], "max": [3, 1, 1]}
        ]
    })"));
    const std::string objPath = dir.getPath("two.obj");
    exportObj(scene, objPath);
    // Two materials whose names meet once blanks become underscores stay two materials.
    const ObjModel back = importObj(objPath);
    ASSERT_EQ(back.materials.size(), 2u);
    EXPECT_NE(back.materials[0].name, back.materials[1].name);
    EXPECT_NE(back.materials[0].diffuse, back.materials[1].diffuse);
    // "-o x.mtl" would have written the MTL and then the OBJ over it.
    EXPECT_THROW(exportObj(scene, dir.getPath("two.mtl")), InputError);
}

} // namespace
} // namespace ispm::test
