// Checked reads of glTF accessors (tinygltf's model): every index, type, stride and byte range is
// tested before a byte is read, and a failure names the file and the JSON path of what is wrong.
// Internal to the glTF importer.
#pragma once

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ispm {

struct GltfFile {
    const tinygltf::Model& model;
    std::string path; // the file, for messages

    // InputError "<path>: <jsonPath>: expected <what>".
    [[noreturn]] void fail(const std::string& jsonPath, const std::string& what) const;
};

// POSITION: VEC3 of floats, each finite.
std::vector<glm::vec3> readPositions(const GltfFile& file, int accessor,
                                     const std::string& usePath);
// NORMAL: VEC3 of floats, each finite, normalised; one of zero length fails naming its index.
std::vector<glm::vec3> readNormals(const GltfFile& file, int accessor, const std::string& usePath);
// TANGENT: VEC4 of floats, each finite, xyz normalised, w the handedness (+-1); a tangent of
// zero length or w = 0 fails naming its index.
std::vector<glm::vec4> readTangents(const GltfFile& file, int accessor, const std::string& usePath);
// TEXCOORD_n: VEC2 of floats, or of normalised unsigned bytes or shorts.
std::vector<glm::vec2> readTexcoords(const GltfFile& file, int accessor,
                                     const std::string& usePath);
// Indices: SCALAR unsigned bytes, shorts or ints, each below vertexCount.
std::vector<uint32_t> readIndices(const GltfFile& file, int accessor, size_t vertexCount,
                                  const std::string& usePath);

} // namespace ispm
