// Wavefront OBJ: import of one file (tinyobjloader) into a mesh and its MTL materials, and export
// of a whole scene as world-space triangles with an MTL file, so Blender can open what we render.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ispm {

inline constexpr uint32_t kNoObjMaterial = 0xffffffffu; // a face without `usemtl`

struct ObjModel {
    // All groups of the file as one mesh; only referenced vertices are kept. triangleMaterials
    // index into `materials`, or are kNoObjMaterial.
    Mesh mesh;
    std::vector<Material> materials; // named as in the MTL file
    // map_Kd images; the materials' diffuseTexture index here (not yet Scene::textures).
    std::vector<SceneTexture> textures;
    size_t droppedDegenerateCount = 0; // zero-area triangles left out
    std::string warnings;              // tinyobjloader's, e.g. an MTL file it could not find
};

// Throws std::runtime_error with tinyobjloader's message (without the file name) when the file
// cannot be read or parsed. MTL mapping: Kd -> diffuse, Ks -> specular, Ns -> phong_exponent,
// Ke -> emission, map_Kd -> a texture multiplying Kd (sRGB, read relative to the OBJ's folder;
// faces of such materials take their vt coordinates, v flipped to run down the image); Tf ->
// transmissive and Ni -> ior only for the refracting illumination models (illum 4, 6, 7, 9):
// exporters write "Tf 1 1 1" for opaque materials too.
// Face corners with a vn get it as their shading normal (normalised; one vertex per (v, vt, vn)
// triple), corners without one are flat-shaded; a vn of zero length throws naming its index.
ObjModel importObj(const std::string& objPath);

// Writes every instance's triangles in world space to `objPath` ("o" per instance, "usemtl" per
// material run) and the scene's materials to the .mtl beside it (Kd, Ks, Ns, Ni, Ke, Tf, illum,
// map_Kd). Textures are written beside it as PNG files (<obj stem>_texture<i>.png) and textured
// meshes get vt coordinates; shading normals are written as world-space vn on the triangles
// that have one at every corner.
// Throws std::runtime_error naming the file on I/O failure.
void exportObj(const Scene& scene, const std::string& objPath);

} // namespace ispm
