// OBJ + MTL export of a whole scene in world space, with its textures as PNG files. Numbers are
// written with std::to_chars: shortest round-trip form, independent of the C++ locale.
#include "scene/obj_io.h"

#include "core/file_write.h"
#include "core/input_error.h"
#include "core/strings.h"

#include <stb_image_write.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace ispm {

namespace {

constexpr uint32_t kUnmapped = 0xffffffffu;
constexpr int kIllumHighlight = 2;      // Phong: diffuse + specular highlight
constexpr int kIllumRefractFresnel = 7; // what we write for transmissive materials

std::string sanitizeName(const std::string& name, const char* fallbackPrefix, size_t index) {
    if (name.empty()) return strCat(fallbackPrefix, index);
    std::string out = name;
    for (char& c : out) {
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = '_';
    }
    return out;
}

// Appends a float in its shortest form that reads back to the same value.
void appendFloat(std::string& out, float v) {
    constexpr size_t kMaxFloatChars = 32; // to_chars needs at most ~15 for a float
    std::array<char, kMaxFloatChars> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
    out.append(buffer.data(), result.ptr);
}

void appendVec3(std::string& out, const char* keyword, const glm::vec3& v) {
    out += keyword;
    for (int i = 0; i < 3; ++i) {
        out += ' ';
        appendFloat(out, v[i]);
    }
    out += '\n';
}

// A texture as PNG bytes (8-bit RGBA, its sRGB codes as they are).
std::string encodePng(const SceneTexture& texture) {
    constexpr int kRgbaChannels = 4;
    std::string out;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<size_t>(size));
    };
    if (stbi_write_png_to_func(append, &out, texture.width, texture.height, kRgbaChannels,
                               texture.rgba.data(), texture.width * kRgbaChannels) == 0) {
        throw std::runtime_error(strCat("cannot encode texture '", texture.name, "' as PNG"));
    }
    return out;
}

} // namespace

void exportObj(const Scene& scene, const std::string& objPath) {
    const std::filesystem::path path(objPath);
    std::string extension = path.extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".obj") {
        // The MTL goes beside it under the same name: "-o x.mtl" would write the MTL and then
        // the OBJ over it.
        throw InputError(strCat("-o: expected a file ending in .obj, got '", objPath, "'"));
    }
    std::filesystem::path mtlPath = path;
    mtlPath.replace_extension(".mtl");

    // Textures as PNG files beside the OBJ, named after it.
    std::vector<std::string> textureFiles;
    std::vector<std::string> textureBytes;
    for (size_t i = 0; i < scene.textures.size(); ++i) {
        textureFiles.push_back(strCat(path.stem().string(), "_texture", i, ".png"));
        textureBytes.push_back(encodePng(scene.textures[i]));
    }

    std::vector<std::string> names;
    std::string mtl = "# ispm scene materials\n";
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        std::string name = sanitizeName(m.name, "material_", i);
        // Names that differ only in blanks would meet: later ones take their index.
        if (std::find(names.begin(), names.end(), name) != names.end()) name += strCat("_", i);
        names.push_back(name);
        const bool isTransmissive = m.transmissive != glm::vec3(0.0f);
        mtl += "\nnewmtl " + names.back() + "\n";
        appendVec3(mtl, "Kd", m.diffuse);
        if (m.diffuseTexture != kNoTexture) {
            mtl += "map_Kd " + textureFiles.at(m.diffuseTexture) + "\n";
            // The texture's alpha cuts the surface out (read back at a cutoff of 0.5).
            if (m.alphaCutoff > 0.0f) mtl += "map_d " + textureFiles.at(m.diffuseTexture) + "\n";
        }
        appendVec3(mtl, "Ks", m.specular);
        mtl += "Ns ";
        appendFloat(mtl, m.phongExponent);
        mtl += "\nNi ";
        appendFloat(mtl, m.ior);
        mtl += "\n";
        if (m.emission != glm::vec3(0.0f)) appendVec3(mtl, "Ke", m.emission);
        if (isTransmissive) appendVec3(mtl, "Tf", m.transmissive);
        mtl += strCat("illum ", isTransmissive ? kIllumRefractFresnel : kIllumHighlight, "\n");
    }

    std::string obj = strCat("# ispm scene, world-space triangles (metres)\nmtllib ",
                             mtlPath.filename().string(), "\n");
    size_t vertexBase = 1; // OBJ indices are 1-based and global over the file
    size_t texcoordBase = 1;
    size_t normalBase = 1;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes.at(instance.meshIndex);
        obj += "o " + sanitizeName(mesh.name, "mesh_", instance.meshIndex) + "\n";
        for (const glm::vec3& p : mesh.positions) {
            appendVec3(obj, "v", glm::vec3(instance.worldFromObject * glm::vec4(p, 1.0f)));
        }
        const bool hasTexcoords = !mesh.texcoords.empty();
        for (const glm::vec2& uv : mesh.texcoords) {
            obj += "vt ";
            appendFloat(obj, uv.x);
            obj += ' ';
            appendFloat(obj, 1.0f - uv.y); // OBJ's v runs up the image
            obj += '\n';
        }
        // vn for the positions with a shading normal, in world space (the inverse transpose);
        // the others' corners, and so their triangles, stay flat.
        const glm::mat3 normalFromObject =
            glm::transpose(glm::inverse(glm::mat3(instance.worldFromObject)));
        std::vector<size_t> normalIndex(mesh.normals.size(), 0); // 0: none (OBJ counts from 1)
        for (size_t v = 0; v < mesh.normals.size(); ++v) {
            if (mesh.normals[v] == glm::vec3(0.0f)) continue;
            appendVec3(obj, "vn", glm::normalize(normalFromObject * mesh.normals[v]));
            normalIndex[v] = normalBase++;
        }
        const auto corner = [&](uint32_t v, bool smooth) {
            const std::string vt = hasTexcoords ? strCat(texcoordBase + v) : "";
            if (smooth) return strCat(vertexBase + v, "/", vt, "/", normalIndex[v]);
            return hasTexcoords ? strCat(vertexBase + v, "/", vt) : strCat(vertexBase + v);
        };
        uint32_t currentMaterial = kUnmapped;
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const uint32_t material = mesh.triangleMaterials.at(t);
            if (material != currentMaterial) {
                obj += "usemtl " + names.at(material) + "\n";
                currentMaterial = material;
            }
            const glm::uvec3& tri = mesh.triangles[t];
            const bool smooth = !normalIndex.empty() && normalIndex[tri.x] != 0 &&
                                normalIndex[tri.y] != 0 && normalIndex[tri.z] != 0;
            obj += strCat("f ", corner(tri.x, smooth), " ", corner(tri.y, smooth), " ",
                          corner(tri.z, smooth), "\n");
        }
        vertexBase += mesh.positions.size();
        texcoordBase += mesh.texcoords.size();
    }
    // All land or none: no cut OBJ, no MTL without its OBJ.
    std::vector<std::pair<std::string, std::string_view>> files;
    for (size_t i = 0; i < textureFiles.size(); ++i)
        files.emplace_back((path.parent_path() / textureFiles[i]).string(), textureBytes[i]);
    files.emplace_back(mtlPath.string(), mtl);
    files.emplace_back(path.string(), obj);
    writeFilesWhole(files);
}

} // namespace ispm
