// glTF files written by the tests themselves (tinygltf's writer), so the importer is checked on
// files it did not make: a floor with a checker base colour texture, a white ceiling, a spot
// light and a camera; a tessellated sphere with or without normals; and a leaf card, a square
// whose texture's alpha cuts a disc out of it, over a floor; a normal-mapped square.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <string>

namespace ispm::test {

struct CheckerRoom {
    float halfM = 1.0f;     // the floor (y = 0) and ceiling span x, z in [-half, half]
    float ceilingM = 2.0f;  // the ceiling's height (white; 0: no ceiling)
    int checks = 4;         // checker squares per side of the floor
    int texelsPerCheck = 8; // texture resolution
    std::array<uint8_t, 3> colorA{255, 0, 0};     // sRGB; square (0, 0) at the texture's top left
    std::array<uint8_t, 3> colorB{255, 255, 255}; // sRGB
    float lightHeightM = 1.0f;                    // the spot at (0, height, 0)
    bool lightUp = false;                         // shines up (+y) instead of down
    float candela = 683.0f;                       // 1 W/sr in ispm's units
    float outerConeRad = 1.2f;
    float innerConeRad = 1.1f;
    glm::vec3 cameraPositionM{0.0f, 1.0f, 0.0f};
    bool cameraUp = false; // looks up (+y) instead of down
    float cameraYFovRad = 1.2f;
};

// Writes the room as a .gltf with embedded buffers and image (data URIs), or as a binary .glb
// when the path ends in .glb.
void writeCheckerRoomGltf(const std::string& path, const CheckerRoom& room);

// A white floor (y = 0, x and z in [-floorHalf, floorHalf]), above it a card facing up at
// cardHeight whose texture is green inside a disc (alpha 1) and transparent outside (alpha 0), and
// a spot light pointing down at (0, lightHeight, 0); the camera looks down from cameraHeight.
struct LeafCard {
    float floorHalfM = 1.0f;
    float cardHalfM = 0.25f;
    float cardHeightM = 0.5f;
    float discRadius = 0.4f; // in the texture's size: the disc fills 0.5 of the card's area
    int texelsPerSide = 64;
    std::string alphaMode = "MASK";
    double alphaCutoff = 0.5;
    double factorAlpha = 1.0; // baseColorFactor's alpha
    float lightHeightM = 1.0f;
    float candela = 683.0f; // 1 W/sr in ispm's units
    float outerConeRad = 1.2f;
    float innerConeRad = 1.1f;
    float cameraHeightM = 2.5f;
    float cameraYFovRad = 0.75f;
};

// Writes the card as a .gltf with embedded buffers and image. The floor is node (and instance)
// 0, the card 1.
void writeLeafCardGltf(const std::string& path, const LeafCard& card);

// Linear colour of the checker square (i, j) (i along +x, j along +z), sRGB decoded.
glm::vec3 getCheckerColor(const CheckerRoom& room, int i, int j);

// A UV sphere centred on the origin: `segments` around the y axis, `rings` from pole to pole,
// every vertex on the sphere, triangles counter-clockwise seen from outside, one diffuse
// material of base colour `albedo`; no lights, no cameras.
struct TessellatedSphere {
    float radiusM = 1.0f;
    int segments = 96;
    int rings = 48;
    float albedo = 0.5f;
    bool withNormals = true; // NORMAL: the sphere's own normal at each vertex; else flat
    int badNormalIndex = -1; // >= 0: that vertex's NORMAL is badNormal (error tests)
    glm::vec3 badNormal{0.0f};
};

// Writes the sphere as a .gltf with an embedded buffer. Returns its vertex count.
int writeSphereGltf(const std::string& path, const TessellatedSphere& sphere);

// A square on y = 0 facing up (x and z in [-half, half]), white, with a normal map whose every
// texel is `texel` (linear RGB bytes: the tangent-space normal 2 rgb / 255 - 1); no lights, no
// cameras. How its texture coordinates lie on it decides the tangent frame:
// - Standard: u along +x, v along +z. Tangent +x; the bitangent, up the image (-v), is -z =
//   cross(+y, +x): handedness +1, TANGENT (1, 0, 0, 1).
// - FlippedV: u along +x, v along -z. Tangent +x; the bitangent is +z = -cross(+y, +x):
//   handedness -1, TANGENT (1, 0, 0, -1).
// - Rotated (the standard layout turned by 90 degrees): u along +z, v along -x. Tangent +z; the
//   bitangent is +x = cross(+y, +z): handedness +1, TANGENT (0, 0, 1, 1).
enum class PlaneUv { Standard, FlippedV, Rotated };
struct NormalMappedPlane {
    float halfM = 1.0f;
    std::array<uint8_t, 3> texel{128, 128, 255};
    int texelsPerSide = 4;
    PlaneUv uv = PlaneUv::Standard;
    bool writeTangents = false; // TANGENT as listed above; else the importer generates them
    bool writeNormals = true;   // NORMAL (0, 1, 0) at every corner; else flat
};

// Writes the plane as a .gltf with embedded buffer and image.
void writeNormalMappedPlaneGltf(const std::string& path, const NormalMappedPlane& plane);

// The tangent TANGENT holds for `uv` (as listed above).
glm::vec4 getPlaneTangent(PlaneUv uv);

} // namespace ispm::test
