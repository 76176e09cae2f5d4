// Shading normals on import: OBJ vn and glTF NORMAL read per corner, generated ones
// (smooth_angle_deg) joined within the angle and split beyond it, and bad normals refused.
#include "core/input_error.h"
#include "scene/mesh_normals.h"
#include "scene/obj_io.h"
#include "scene_test_util.h"
#include "support/gltf_scenes.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace ispm::test {
namespace {

// Two triangles folded 90 degrees along the edge x = 0 (the floor y = 0 and the wall x = 0),
// with a vn per corner: each face's own normal (flat) or the fold's bisector on the edge.
std::string makeFoldObj(bool smooth) {
    std::string text = "v 0 0 -1\nv 0 0 1\nv 1 0 0\nv 0 1 0\n";
    text += "vn 0 1 0\nvn 1 0 0\nvn 1 1 0\n";
    // Floor (0 1 2 seen from +y: counter-clockwise), wall (0 3 1 seen from +x).
    text +=
        smooth ? "f 1//3 2//3 3//1\nf 1//3 4//2 2//3\n" : "f 1//1 2//1 3//1\nf 1//2 4//2 2//2\n";
    return text;
}

std::string makeObjScene(const std::string& extra = "") {
    return R"({"camera": {"position": [3, 3, 3], "target": [0, 0, 0]},
               "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
               "objects": [{"type": "mesh", "obj": "fold.obj", "material": "grey")" +
           extra + "}]}";
}

TEST(MeshNormals, ObjVnSplitsVerticesPerNormal) {
    ScratchDir dir;
    dir.write("fold.obj", makeFoldObj(false));
    const Scene flat = loadScene(dir.write("s.json", makeObjScene()));
    const Mesh& mesh = flat.meshes.at(0);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    // The edge's two positions carry two normals each: four vertices on it, two off it.
    EXPECT_EQ(mesh.positions.size(), 6u);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::vec3 face = glm::normalize(
            glm::cross(mesh.positions[mesh.triangles[t].y] - mesh.positions[mesh.triangles[t].x],
                       mesh.positions[mesh.triangles[t].z] - mesh.positions[mesh.triangles[t].x]));
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(glm::dot(mesh.normals[mesh.triangles[t][k]], face), 1.0f, 1e-6f);
    }
}

TEST(MeshNormals, ObjSmoothAndFlatVnDifferOnlyOnTheFold) {
    ScratchDir dir;
    dir.write("fold.obj", makeFoldObj(true));
    const Scene smooth = loadScene(dir.write("s.json", makeObjScene()));
    const Mesh& mesh = smooth.meshes.at(0);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_EQ(mesh.positions.size(), 4u); // one normal per position: nothing split
    const float halfSqrt2 = glm::root_two<float>() / 2.0f;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        const glm::vec3 n = mesh.normals[v];
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f); // vn 1 1 0 normalised
        if (p.x == 0.0f && p.y == 0.0f) {         // on the fold: the bisector
            EXPECT_NEAR(n.x, halfSqrt2, 1e-6f);
            EXPECT_NEAR(n.y, halfSqrt2, 1e-6f);
        } else { // off it: the face's own
            EXPECT_NEAR(glm::dot(n, p.x > 0.0f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)), 1.0f,
                        1e-6f);
        }
    }
}

TEST(MeshNormals, ObjWithoutVnStaysFlat) {
    ScratchDir dir;
    dir.write("fold.obj", "v 0 0 -1\nv 0 0 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 4 2\n");
    EXPECT_TRUE(loadScene(dir.write("s.json", makeObjScene())).meshes.at(0).normals.empty());
}

TEST(MeshNormals, GeneratedNormalsJoinWithinTheAngleAndSplitBeyond) {
    ScratchDir dir;
    dir.write("fold.obj", "v 0 0 -1\nv 0 0 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 4 2\n");
    // 90 degrees apart: joined at a threshold of 90 (the bisector on the fold) ...
    const Scene joined =
        loadScene(dir.write("a.json", makeObjScene(R"(, "smooth_angle_deg": 90)")));
    const Mesh& a = joined.meshes.at(0);
    EXPECT_EQ(a.positions.size(), 4u);
    for (size_t v = 0; v < a.positions.size(); ++v) {
        if (a.positions[v].x == 0.0f && a.positions[v].y == 0.0f) {
            EXPECT_NEAR(a.normals[v].x, a.normals[v].y, 1e-6f);
        }
    }
    // ... split below it: every corner keeps its face's normal.
    const Scene split = loadScene(dir.write("b.json", makeObjScene(R"(, "smooth_angle_deg": 60)")));
    const Mesh& b = split.meshes.at(0);
    EXPECT_EQ(b.positions.size(), 6u);
    for (const glm::uvec3& tri : b.triangles)
        EXPECT_EQ(b.normals[tri.x], b.normals[tri.z]);
}

TEST(MeshNormals, GeneratedNormalsOfATessellatedSphereApproachTheSphere) {
    ScratchDir dir;
    TessellatedSphere sphere;
    sphere.withNormals = false;
    sphere.segments = 32;
    sphere.rings = 16;
    writeSphereGltf(dir.getPath("sphere.gltf"), sphere);
    const Scene scene =
        loadScene(dir.write("s.json", R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
                      "objects": [{"type": "gltf", "path": "sphere.gltf", "smooth_angle_deg": 30}],
                      "lights": [{"type": "point", "position": [0, 3, 0], "intensity": [1, 1, 1]}]})"));
    const Mesh& mesh = scene.meshes.at(0);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        // Angle-weighted means of the faces around a vertex: within a degree of the sphere's.
        EXPECT_GT(glm::dot(mesh.normals[v], glm::normalize(mesh.positions[v])),
                  std::cos(glm::radians(1.0f)))
            << "vertex " << v;
    }
}

TEST(MeshNormals, ExportedObjCarriesTheNormalsInWorldSpace) {
    ScratchDir dir;
    dir.write("fold.obj", makeFoldObj(true));
    // Turned a quarter about y: +x goes to -z.
    const Scene scene =
        loadScene(dir.write("s.json", makeObjScene(R"(, "rotate_deg": [0, 90, 0])")));
    exportObj(scene, dir.getPath("out.obj"));
    const ObjModel back = importObj(dir.getPath("out.obj"));
    const Mesh& mesh = back.mesh;
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    const float halfSqrt2 = glm::root_two<float>() / 2.0f;
    int onFold = 0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        const glm::vec3 n = mesh.normals[v];
        if (std::abs(p.z) < 1e-6f && std::abs(p.y) < 1e-6f) { // on the fold: the bisector
            EXPECT_NEAR(n.z, -halfSqrt2, 1e-5f);
            EXPECT_NEAR(n.y, halfSqrt2, 1e-5f);
            ++onFold;
        }
    }
    EXPECT_EQ(onFold, 2);
}

TEST(MeshNormals, ZeroLengthObjVnNamesTheFileAndIndex) {
    ScratchDir dir;
    dir.write("fold.obj", "v 0 0 -1\nv 0 0 1\nv 1 0 0\nvn 0 1 0\nvn 0 0 0\nf 1//1 2//2 3//1\n");
    const std::string error = getLoadError(dir, makeObjScene());
    EXPECT_TRUE(contains(error, "fold.obj")) << error;
    EXPECT_TRUE(contains(error, "vn 2")) << error;
    EXPECT_TRUE(contains(error, "non-zero length")) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(MeshNormals, NanObjVnNamesTheFileAndLine) {
    ScratchDir dir;
    dir.write("fold.obj", "v 0 0 -1\nv 0 0 1\nv 1 0 0\nvn 0 nan 0\nf 1//1 2//1 3//1\n");
    const std::string error = getLoadError(dir, makeObjScene());
    EXPECT_TRUE(contains(error, "fold.obj")) << error;
    EXPECT_TRUE(contains(error, "line 4 (vn)")) << error;
}

TEST(MeshNormals, BadGltfNormalNamesTheFileAccessorAndElement) {
    ScratchDir dir;
    const std::string scene =
        R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
            "objects": [{"type": "gltf", "path": "sphere.gltf"}],
            "lights": [{"type": "point", "position": [0, 3, 0], "intensity": [1, 1, 1]}]})";
    for (const glm::vec3 bad : {glm::vec3(0.0f), glm::vec3(std::nanf(""), 0.0f, 1.0f)}) {
        TessellatedSphere sphere;
        sphere.segments = 8;
        sphere.rings = 4;
        sphere.badNormalIndex = 7;
        sphere.badNormal = bad;
        writeSphereGltf(dir.getPath("sphere.gltf"), sphere);
        const std::string error = getLoadError(dir, scene);
        EXPECT_TRUE(contains(error, "sphere.gltf")) << error;
        EXPECT_TRUE(contains(error, "/accessors/1")) << error; // NORMAL, after POSITION
        EXPECT_TRUE(contains(error, "element 7")) << error;
    }
}

TEST(MeshNormals, SmoothAngleOutOfRangeIsRefused) {
    ScratchDir dir;
    dir.write("fold.obj", "v 0 0 -1\nv 0 0 1\nv 1 0 0\nf 1 2 3\n");
    const std::string error = getLoadError(dir, makeObjScene(R"(, "smooth_angle_deg": 200)"));
    EXPECT_TRUE(contains(error, "/objects/0/smooth_angle_deg")) << error;
}

} // namespace
} // namespace ispm::test
