// Tangent frames for normal maps: tangents generated from positions and texture coordinates
// (computeVertexTangents) against frames worked out by hand, and against the TANGENT a glTF file
// carries for the same quad.
#include "scene/mesh_tangents.h"
#include "scene_test_util.h"
#include "support/gltf_scenes.h"

#include <cmath>

namespace ispm::test {
namespace {

constexpr float kTolerance = 1e-5f; // float rounding of a few products

void expectTangent(glm::vec4 actual, glm::vec4 expected, const char* what) {
    EXPECT_NEAR(actual.x, expected.x, kTolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, kTolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, kTolerance) << what;
    EXPECT_EQ(actual.w, expected.w) << what;
}

// The quad the glTF writer makes, loaded with the file's TANGENT and without it: the importer's
// generated tangents equal the file's at every vertex, for each layout of texture coordinates
// (two handednesses, two directions of u).
TEST(MeshTangents, GeneratedTangentsEqualTheFilesOnAQuad) {
    ScratchDir dir;
    for (const PlaneUv uv : {PlaneUv::Standard, PlaneUv::FlippedV, PlaneUv::Rotated}) {
        for (const bool normals : {true, false}) {
            NormalMappedPlane plane;
            plane.uv = uv;
            plane.writeNormals = normals;
            plane.writeTangents = true;
            writeNormalMappedPlaneGltf(dir.getPath("file.gltf"), plane);
            plane.writeTangents = false;
            writeNormalMappedPlaneGltf(dir.getPath("generated.gltf"), plane);
            const Scene file = loadScene(dir.getPath("file.gltf"));
            const Scene generated = loadScene(dir.getPath("generated.gltf"));
            ASSERT_EQ(file.meshes.size(), 1u);
            ASSERT_EQ(generated.meshes.size(), 1u);
            const std::vector<glm::vec4>& expected = file.meshes[0].tangents;
            const std::vector<glm::vec4>& actual = generated.meshes[0].tangents;
            ASSERT_EQ(expected.size(), 4u);
            ASSERT_EQ(actual.size(), 4u);
            for (size_t v = 0; v < 4; ++v) {
                expectTangent(expected[v], getPlaneTangent(uv), "the file's, as written");
                expectTangent(actual[v], expected[v], "generated");
            }
        }
    }
}

// A tilted, stretched quad whose texture runs at an angle to its edges: the tangent is dP/du
// made perpendicular to the vertex normal, worked out by hand. The quad lies in the plane
// z = 0 with normal +z; u = (x + y) / 2, v = (y - x) / 2. Solving, P(u, v) = (u - v, u + v, 0),
// so dP/du = (1, 1, 0) / sqrt 2 and the image's up, -dP/dv, is (1, -1, 0) / sqrt 2;
// cross(+z, dP/du) = (-1, 1, 0) / sqrt 2 points against it: handedness -1.
TEST(MeshTangents, TangentIsDpDuAndHandednessFollowsTheImagesUp) {
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    std::vector<glm::vec2> texcoords;
    for (const glm::vec3& p : positions)
        texcoords.emplace_back((p.x + p.y) / 2.0f, (p.y - p.x) / 2.0f);
    const std::vector<glm::uvec3> triangles = {{0, 1, 2}, {0, 2, 3}};
    const float s = 1.0f / std::sqrt(2.0f);
    for (const glm::vec4& t : computeVertexTangents(positions, texcoords, {}, triangles))
        expectTangent(t, {s, s, 0.0f, -1.0f}, "face normals");
    // A vertex normal tilted toward +x: the tangent leaves its component along the normal
    // (Gram-Schmidt) and stays unit.
    const glm::vec3 tilted = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
    const std::vector<glm::vec3> normals(4, tilted);
    const glm::vec3 dPdu(s, s, 0.0f);
    const glm::vec3 expected = glm::normalize(dPdu - glm::dot(dPdu, tilted) * tilted);
    for (const glm::vec4& t : computeVertexTangents(positions, texcoords, normals, triangles)) {
        expectTangent(t, glm::vec4(expected, -1.0f), "tilted normals");
        EXPECT_NEAR(glm::dot(glm::vec3(t), tilted), 0.0f, kTolerance);
    }
    // Texture coordinates all alike give no direction: no frame (w = 0).
    const std::vector<glm::vec2> flat(4, glm::vec2(0.5f));
    for (const glm::vec4& t : computeVertexTangents(positions, flat, {}, triangles))
        EXPECT_EQ(t.w, 0.0f);
}

} // namespace
} // namespace ispm::test
