// OBJ import through tinyobjloader, with whole-line checks of the numbers it reads and map_Kd
// textures (export: obj_export.cpp).
#include "scene/obj_io.h"

#include "core/strings.h"
#include "scene/mesh_builder.h"
#include "scene/scene_texture.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ispm {

namespace {

constexpr uint32_t kUnmapped = 0xffffffffu;
constexpr float kMtlAlphaCutoff = 0.5f; // map_d's alpha test: glTF's default alphaCutoff

// MTL illumination models that refract (4: glass, 6: refraction, 7: refraction + Fresnel,
// 9: glass without ray-traced reflection): only these make Tf and Ni mean transmission.
bool isRefractingIllum(int illum) {
    return illum == 4 || illum == 6 || illum == 7 || illum == 9;
}

glm::vec3 toVec3(const tinyobj::real_t* v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

Material convertMaterial(const tinyobj::material_t& m) {
    Material material;
    material.name = m.name;
    material.diffuse = toVec3(m.diffuse);
    material.specular = toVec3(m.specular);
    material.phongExponent = static_cast<float>(m.shininess);
    material.emission = toVec3(m.emission);
    if (isRefractingIllum(m.illum)) {
        material.transmissive = toVec3(m.transmittance);
        material.ior = static_cast<float>(m.ior);
    }
    // What the JSON loader checks for its own materials: finite, not negative, emission bounded
    // like a light (negative reflectances and unbounded emission were accepted).
    const auto check = [&m](const char* key, glm::vec3 v, float hi) {
        for (int i = 0; i < 3; ++i) {
            if (!(v[i] >= 0.0f && v[i] <= hi)) {
                throw std::runtime_error(strCat("material '", m.name, "': ", key, " ", v[i],
                                                ": expected a number in [0, ", hi, "]"));
            }
        }
    };
    constexpr float kMaxReflectance = 1.0f;
    constexpr float kMaxEmission = 1e12f; // W/(m^2 sr), as light intensities
    check("Kd", material.diffuse, kMaxReflectance);
    check("Ks", material.specular, kMaxReflectance);
    check("Tf", material.transmissive, kMaxReflectance);
    check("Ke", material.emission, kMaxEmission);
    if (!std::isfinite(material.phongExponent) || !std::isfinite(material.ior)) {
        throw std::runtime_error(strCat("material '", m.name, "': Ns or Ni is not finite"));
    }
    return material;
}

// Whole-line checks of the numbers tinyobjloader reads: it turns a token it cannot read ("nan",
// "inf", "1.0x") into 0 and wraps face indices past int, silently. Each number of a vertex
// (v, vn, vt), face (f: the first of each slash group; the others are not used) and material
// (MTL colours, exponents, opacity, illumination model) must read whole, be finite, and face
// indices must fit. Throws with the file, line and token.
bool readWholeDouble(std::string_view token, double& value) {
    if (token.size() > 1 && token.front() == '+') token.remove_prefix(1); // from_chars takes no '+'
    const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
    return result.ec == std::errc() && result.ptr == token.data() + token.size() &&
           std::isfinite(value);
}

std::vector<std::string_view> splitTokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at])))
            ++at;
        const size_t start = at;
        while (at < line.size() && !std::isspace(static_cast<unsigned char>(line[at])))
            ++at;
        if (at > start) tokens.push_back(line.substr(start, at - start));
    }
    return tokens;
}

void checkNumbers(const std::filesystem::path& path, bool isMtl) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return; // tinyobjloader reports a missing OBJ; a missing MTL is its warning
    // The OBJ's own name is in the caller's message; an MTL's is not.
    const std::string where = isMtl ? strCat("'", path.filename().string(), "' line ") : "line ";
    std::string line;
    for (size_t lineNumber = 1; std::getline(in, line); ++lineNumber) {
        const std::vector<std::string_view> tokens = splitTokens(line);
        if (tokens.empty() || tokens[0].front() == '#') continue;
        const std::string_view key = tokens[0];
        const auto fail = [&](std::string_view token, const char* expected) {
            throw std::runtime_error(strCat(where, lineNumber, " (", key, "): expected ", expected,
                                            ", got '", token, "'"));
        };
        if (!isMtl && key == "mtllib") {
            for (size_t i = 1; i < tokens.size(); ++i)
                checkNumbers(path.parent_path() / std::string(tokens[i]), true);
            continue;
        }
        if (!isMtl && key == "f") {
            for (size_t i = 1; i < tokens.size(); ++i) {
                const std::string_view first = tokens[i].substr(0, tokens[i].find('/'));
                std::string_view digits = first;
                if (digits.size() > 1 && digits.front() == '+') digits.remove_prefix(1);
                int index = 0;
                const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), index);
                if (r.ec != std::errc() || r.ptr != digits.data() + digits.size() || index == 0) {
                    fail(tokens[i],
                         "a vertex index (a non-zero whole number that fits in 32 bits)");
                }
            }
            continue;
        }
        static constexpr std::array<std::string_view, 3> kObjNumbers = {"v", "vn", "vt"};
        static constexpr std::array<std::string_view, 11> kMtlNumbers = {
            "Ka", "Kd", "Ks", "Ke", "Kt", "Tf", "Ns", "Ni", "d", "Tr", "illum"};
        const bool numeric =
            isMtl ? std::find(kMtlNumbers.begin(), kMtlNumbers.end(), key) != kMtlNumbers.end()
                  : std::find(kObjNumbers.begin(), kObjNumbers.end(), key) != kObjNumbers.end();
        if (!numeric) continue;
        for (size_t i = 1; i < tokens.size(); ++i) {
            // MTL colours may be given as "xyz x y z" or "spectral file.rfl" (not read).
            if (isMtl && i == 1 && (tokens[i] == "xyz" || tokens[i] == "spectral")) break;
            double value = 0.0;
            if (!readWholeDouble(tokens[i], value)) fail(tokens[i], "a finite number");
        }
    }
}

} // namespace

ObjModel importObj(const std::string& objPath) {
    checkNumbers(objPath, false);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(objPath, config)) {
        throw std::runtime_error(reader.Error().empty() ? "unreadable OBJ file" : reader.Error());
    }
    ObjModel model;
    model.warnings = reader.Warning();
    const std::filesystem::path folder = std::filesystem::path(objPath).parent_path();
    for (const tinyobj::material_t& m : reader.GetMaterials()) {
        model.materials.push_back(convertMaterial(m));
        if (!m.diffuse_texname.empty()) {
            const std::filesystem::path texturePath = folder / m.diffuse_texname;
            try {
                model.textures.push_back(readTextureFile(texturePath.string()));
            } catch (const std::runtime_error& e) {
                throw std::runtime_error(strCat("material '", m.name, "': map_Kd '",
                                                texturePath.string(), "': ", e.what()));
            }
            model.materials.back().diffuseTexture =
                static_cast<uint32_t>(model.textures.size() - 1);
            // map_d naming the map_Kd image: its alpha cuts the surface out, as glTF's MASK at
            // its default cutoff (exporters write leaves so). A map_d of its own and `d` are
            // not read: ispm has no partly transparent surface.
            if (m.alpha_texname == m.diffuse_texname) {
                model.materials.back().alphaCutoff = kMtlAlphaCutoff;
            }
        }
    }
    const std::vector<tinyobj::real_t>& uvs = reader.GetAttrib().texcoords;
    const size_t uvCount = uvs.size() / 2;

    const std::vector<tinyobj::real_t>& vertices = reader.GetAttrib().vertices;
    const size_t vertexCount = vertices.size() / 3;
    const std::vector<tinyobj::real_t>& vns = reader.GetAttrib().normals;
    const size_t normalCount = vns.size() / 3;
    std::vector<uint32_t> remap(vertexCount, kUnmapped);
    // Corners of textured faces: one vertex per (position, vt) pair, keyed position << 32 | vt.
    std::unordered_map<uint64_t, uint32_t> texturedRemap;
    // Corners with a vn: one vertex per (position, vt or kUnmapped, vn) triple.
    std::map<std::array<uint32_t, 3>, uint32_t> normalRemap;
    Mesh& mesh = model.mesh;
    mesh.name = std::filesystem::path(objPath).stem().string();
    const auto addPosition = [&](size_t i) {
        const glm::vec3 p = toVec3(&vertices[3 * i]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw std::runtime_error(strCat("vertex ", i + 1, " is not finite"));
        }
        mesh.positions.push_back(p);
        if (!mesh.texcoords.empty()) mesh.texcoords.emplace_back(0.0f);
        if (!mesh.normals.empty()) mesh.normals.emplace_back(0.0f); // flat, until a vn says
        return static_cast<uint32_t>(mesh.positions.size() - 1);
    };
    const auto readTexcoord = [&](const tinyobj::index_t& corner) -> size_t {
        const int uv = corner.texcoord_index;
        if (uv < 0 || static_cast<size_t>(uv) >= uvCount) {
            throw std::runtime_error(strCat("a face of a map_Kd material needs vt coordinates; "
                                            "it refers to vt ",
                                            uv + 1, " of ", uvCount));
        }
        return static_cast<size_t>(uv);
    };
    const auto setTexcoord = [&](uint32_t v, size_t u) {
        mesh.texcoords.resize(mesh.positions.size()); // earlier untextured vertices: (0, 0)
        // OBJ's v runs up the image; the scene's runs down from its top row.
        mesh.texcoords[v] = glm::vec2(uvs[2 * u], 1.0f - uvs[2 * u + 1]);
    };
    const auto useVertex = [&](const tinyobj::index_t& corner, bool textured) -> uint32_t {
        const int index = corner.vertex_index;
        if (index < 0 || static_cast<size_t>(index) >= vertexCount) {
            throw std::runtime_error(
                strCat("face refers to vertex ", index + 1, " of ", vertexCount));
        }
        const auto i = static_cast<size_t>(index);
        if (corner.normal_index >= 0) {
            const auto vn = static_cast<size_t>(corner.normal_index);
            if (vn >= normalCount) {
                throw std::runtime_error(strCat("face refers to vn ", vn + 1, " of ", normalCount));
            }
            const size_t u = textured ? readTexcoord(corner) : kUnmapped;
            const std::array<uint32_t, 3> key = {static_cast<uint32_t>(i), static_cast<uint32_t>(u),
                                                 static_cast<uint32_t>(vn)};
            const auto found = normalRemap.find(key);
            if (found != normalRemap.end()) return found->second;
            const glm::vec3 n = toVec3(&vns[3 * vn]);
            const float length = glm::length(n);
            // Finite already (checkNumbers); a zero normal has no direction to shade with.
            if (!(length > 0.0f && std::isfinite(length))) {
                throw std::runtime_error(strCat("vn ", vn + 1, " (", n.x, " ", n.y, " ", n.z,
                                                "): expected a normal of non-zero length"));
            }
            const uint32_t v = addPosition(i);
            if (textured) setTexcoord(v, u);
            mesh.normals.resize(mesh.positions.size()); // earlier vertices without vn: zero
            mesh.normals[v] = n / length;
            normalRemap.emplace(key, v);
            return v;
        }
        if (!textured) {
            if (remap[i] == kUnmapped) remap[i] = addPosition(i);
            return remap[i];
        }
        const size_t u = readTexcoord(corner);
        const uint64_t key = (uint64_t(i) << 32) | uint64_t(u);
        const auto found = texturedRemap.find(key);
        if (found != texturedRemap.end()) return found->second;
        const uint32_t v = addPosition(i);
        setTexcoord(v, u);
        texturedRemap.emplace(key, v);
        return v;
    };

    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const tinyobj::mesh_t& shapeMesh = shape.mesh;
        size_t offset = 0;
        for (size_t face = 0; face < shapeMesh.num_face_vertices.size(); ++face) {
            const size_t corners = shapeMesh.num_face_vertices[face];
            if (corners != 3) {
                // Triangulation leaves only lines and points (l, p) with other counts: not
                // surfaces.
                offset += corners;
                continue;
            }
            const int materialId =
                face < shapeMesh.material_ids.size() ? shapeMesh.material_ids[face] : -1;
            const bool hasMaterial =
                materialId >= 0 && static_cast<size_t>(materialId) < model.materials.size();
            const bool textured =
                hasMaterial &&
                model.materials[static_cast<size_t>(materialId)].diffuseTexture != kNoTexture;
            const tinyobj::index_t* c = &shapeMesh.indices[offset];
            offset += corners;
            const glm::uvec3 tri{useVertex(c[0], textured), useVertex(c[1], textured),
                                 useVertex(c[2], textured)};
            if (isDegenerateTriangle(mesh.positions[tri.x], mesh.positions[tri.y],
                                     mesh.positions[tri.z])) {
                ++model.droppedDegenerateCount;
                continue;
            }
            mesh.triangles.push_back(tri);
            mesh.triangleMaterials.push_back(hasMaterial ? static_cast<uint32_t>(materialId)
                                                         : kNoObjMaterial);
        }
    }
    return model;
}

} // namespace ispm
