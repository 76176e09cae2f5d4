// glTF files to the scene model: loading through tinygltf, the node hierarchy, meshes and
// cameras (materials and lights in gltf_materials.cpp, checked accessors in gltf_accessors.cpp).
#include "scene/gltf_import.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_materials.h"
#include "scene/mesh_builder.h"
#include "scene/mesh_tangents.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <numeric>
#include <optional>

namespace ispm {

namespace {

constexpr size_t kMatrixElements = 16;
// |det| of a node's 3x3 part below this fraction of its columns' length product: singular.
constexpr float kMinRelativeDeterminant = 1e-9f;

std::string getLowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

bool isGlbPath(const std::string& path) {
    return getLowerExtension(path) == ".glb";
}

std::string flattenMessage(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

glm::mat4 getLocalTransform(const GltfFile& file, const tinygltf::Node& node, size_t index) {
    const std::string at = strCat("/nodes/", index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != kMatrixElements) file.fail(at + "/matrix", "16 numbers");
        glm::mat4 m;
        for (size_t i = 0; i < kMatrixElements; ++i) // column-major, as glm
            glm::value_ptr(m)[i] = float(node.matrix[i]);
        return m;
    }
    glm::mat4 m(1.0f);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3) file.fail(at + "/translation", "3 numbers");
        m = glm::translate(m, glm::vec3(float(node.translation[0]), float(node.translation[1]),
                                        float(node.translation[2])));
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) file.fail(at + "/rotation", "a quaternion (x, y, z, w)");
        const glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                          float(node.rotation[2]));
        if (!(glm::length(q) > 0.0f)) file.fail(at + "/rotation", "a non-zero quaternion");
        m *= glm::mat4_cast(glm::normalize(q));
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3) file.fail(at + "/scale", "3 numbers");
        m = glm::scale(m,
                       glm::vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2])));
    }
    return m;
}

std::vector<uint32_t> makeSequence(size_t count) {
    std::vector<uint32_t> sequence(count, 0u);
    std::iota(sequence.begin(), sequence.end(), 0u);
    return sequence;
}

bool isInvertible(const glm::mat4& m) {
    const glm::mat3 linear(m);
    const float scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return std::fabs(glm::determinant(linear)) > kMinRelativeDeterminant * scale;
}

// A normal-mapped primitive's tangents: its TANGENT, or generated from its positions and
// texture coordinates where it has none (computeVertexTangents; docs/design.md "Normal maps").
std::vector<glm::vec4> readOrComputeTangents(const GltfFile& file, const tinygltf::Primitive& prim,
                                             const std::string& at,
                                             const std::vector<glm::vec3>& positions,
                                             const std::vector<glm::vec2>& texcoords,
                                             const std::vector<glm::vec3>& normals,
                                             const std::vector<uint32_t>& indices) {
    if (const auto tangent = prim.attributes.find("TANGENT"); tangent != prim.attributes.end()) {
        std::vector<glm::vec4> tangents =
            readTangents(file, tangent->second, at + "/attributes/TANGENT");
        if (tangents.size() != positions.size()) {
            file.fail(at + "/attributes/TANGENT", "as many tangents as positions");
        }
        return tangents;
    }
    std::vector<glm::uvec3> triangles;
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
        triangles.emplace_back(indices[t], indices[t + 1], indices[t + 2]);
    return computeVertexTangents(positions, texcoords, normals, triangles);
}

// The importer's state while it walks the nodes.
struct GltfImporter {
    const GltfFile& file;
    Scene& scene;
    std::string prefix; // material name prefix
    GltfMaterials materials;
    std::vector<std::optional<uint32_t>> sceneMeshes; // per glTF mesh, once converted
    std::vector<std::pair<std::string, Camera>> cameras;
    size_t triangleCount = 0;

    uint32_t convertMesh(int index, const std::string& usePath);
    void addCamera(int index, const glm::mat4& worldFromNode, const tinygltf::Node& node,
                   const std::string& usePath);
    void visit(size_t node, const glm::mat4& parent, std::vector<bool>& onPath);
};

uint32_t GltfImporter::convertMesh(int index, const std::string& usePath) {
    const tinygltf::Model& model = file.model;
    if (index < 0 || static_cast<size_t>(index) >= model.meshes.size()) {
        file.fail(usePath, strCat("a mesh index below ", model.meshes.size(), ", got ", index));
    }
    const auto meshIndex = static_cast<size_t>(index);
    if (sceneMeshes[meshIndex]) return *sceneMeshes[meshIndex];
    const tinygltf::Mesh& in = model.meshes[meshIndex];
    Mesh mesh;
    mesh.name = in.name.empty() ? strCat("mesh_", meshIndex) : in.name;
    for (size_t p = 0; p < in.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = in.primitives[p];
        const std::string at = strCat("/meshes/", meshIndex, "/primitives/", p);
        // Points and lines (modes 0-3) are not surfaces; strips and fans are not read.
        constexpr int kLastLineMode = 3;
        if (prim.mode <= kLastLineMode) continue;
        if (prim.mode != TINYGLTF_MODE_TRIANGLES) file.fail(at + "/mode", "4 (triangles)");
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) {
            file.fail(at + "/attributes", "a POSITION attribute");
        }
        const std::vector<glm::vec3> positions =
            readPositions(file, position->second, at + "/attributes/POSITION");
        // Without indices, the vertices in order are the triangles' corners.
        const std::vector<uint32_t> indices =
            prim.indices >= 0 ? readIndices(file, prim.indices, positions.size(), at + "/indices")
                              : makeSequence(positions.size());
        if (indices.size() % 3 != 0) file.fail(at, "a multiple of 3 indices (triangles)");
        uint32_t material = 0;
        int texcoordSet = -1;
        if (prim.material < 0) {
            material = getGltfDefaultMaterial(materials, prefix, scene);
        } else if (static_cast<size_t>(prim.material) < materials.sceneIndex.size()) {
            material = materials.sceneIndex[static_cast<size_t>(prim.material)];
            texcoordSet = materials.texcoordSet[static_cast<size_t>(prim.material)];
        } else {
            file.fail(at + "/material",
                      strCat("a material index below ", materials.sceneIndex.size()));
        }
        std::vector<glm::vec2> texcoords;
        if (texcoordSet >= 0) {
            const std::string name = strCat("TEXCOORD_", texcoordSet);
            const auto uv = prim.attributes.find(name);
            if (uv == prim.attributes.end()) {
                file.fail(at + "/attributes",
                          strCat("a ", name, " attribute (its material's textures use it)"));
            }
            texcoords = readTexcoords(file, uv->second, at + "/attributes/" + name);
            if (texcoords.size() != positions.size()) {
                file.fail(at + "/attributes/" + name, "as many texture coordinates as positions");
            }
            mesh.texcoords.resize(mesh.positions.size()); // earlier primitives: untextured
        }
        // Without NORMAL a primitive is flat-shaded, as the glTF spec asks.
        std::vector<glm::vec3> normals;
        if (const auto normal = prim.attributes.find("NORMAL"); normal != prim.attributes.end()) {
            normals = readNormals(file, normal->second, at + "/attributes/NORMAL");
            if (normals.size() != positions.size()) {
                file.fail(at + "/attributes/NORMAL", "as many normals as positions");
            }
            mesh.normals.resize(mesh.positions.size()); // earlier primitives: flat (zero)
        }
        std::vector<glm::vec4> tangents;
        if (scene.materials[material].normalTexture != kNoTexture) {
            tangents =
                readOrComputeTangents(file, prim, at, positions, texcoords, normals, indices);
            mesh.tangents.resize(mesh.positions.size()); // earlier primitives: none (w = 0)
        }
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
        if (!normals.empty()) {
            mesh.normals.insert(mesh.normals.end(), normals.begin(), normals.end());
        } else if (!mesh.normals.empty()) {
            mesh.normals.resize(mesh.positions.size());
        }
        if (!tangents.empty()) {
            mesh.tangents.insert(mesh.tangents.end(), tangents.begin(), tangents.end());
        } else if (!mesh.tangents.empty()) {
            mesh.tangents.resize(mesh.positions.size());
        }
        if (!texcoords.empty()) {
            mesh.texcoords.insert(mesh.texcoords.end(), texcoords.begin(), texcoords.end());
        } else if (!mesh.texcoords.empty()) {
            mesh.texcoords.resize(mesh.positions.size());
        }
        for (size_t t = 0; t + 2 < indices.size(); t += 3) {
            const glm::uvec3 tri(indices[t], indices[t + 1], indices[t + 2]);
            if (isDegenerateTriangle(positions[tri.x], positions[tri.y], positions[tri.z])) {
                continue; // zero area: seen by nothing, and it would break the BVH's planes
            }
            mesh.triangles.push_back(tri + base);
            mesh.triangleMaterials.push_back(material);
        }
    }
    triangleCount += mesh.triangles.size();
    sceneMeshes[meshIndex] = static_cast<uint32_t>(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));
    return *sceneMeshes[meshIndex];
}

void GltfImporter::addCamera(int index, const glm::mat4& worldFromNode, const tinygltf::Node& node,
                             const std::string& usePath) {
    const tinygltf::Model& model = file.model;
    if (index < 0 || static_cast<size_t>(index) >= model.cameras.size()) {
        file.fail(usePath, strCat("a camera index below ", model.cameras.size(), ", got ", index));
    }
    const tinygltf::Camera& in = model.cameras[static_cast<size_t>(index)];
    if (in.type != "perspective") return; // ispm's cameras are pinholes (documented)
    const std::string at = strCat("/cameras/", index, "/perspective");
    const tinygltf::PerspectiveCamera& p = in.perspective;
    // A pinhole sees less than a half space: (0, pi) exclusive.
    if (!(p.yfov > 0.0 && p.yfov < std::numbers::pi))
        file.fail(at + "/yfov", "an angle in (0, pi)");
    if (!(p.znear > 0.0)) file.fail(at + "/znear", "a distance > 0");
    if (!(p.zfar == 0.0 || p.zfar > p.znear)) file.fail(at + "/zfar", "0 (infinite) or > znear");
    Camera camera;
    camera.position = glm::vec3(worldFromNode[3]);
    const glm::vec3 forward(worldFromNode * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    camera.target = camera.position + glm::normalize(forward);
    camera.up = glm::normalize(glm::vec3(worldFromNode * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f)));
    camera.fovYDeg = float(glm::degrees(p.yfov));
    camera.nearM = float(p.znear);
    camera.farM = float(p.zfar); // 0: derived from the scene, as an infinite far plane allows
    const std::string name = !in.name.empty()     ? in.name
                             : !node.name.empty() ? node.name
                                                  : strCat("camera_", index);
    cameras.emplace_back(name, camera);
}

void GltfImporter::visit(size_t index, const glm::mat4& parent, std::vector<bool>& onPath) {
    const tinygltf::Model& model = file.model;
    const std::string at = strCat("/nodes/", index);
    if (onPath[index]) file.fail(at + "/children", "a node tree (this node is its own ancestor)");
    onPath[index] = true;
    const tinygltf::Node& node = model.nodes[index];
    const glm::mat4 world = parent * getLocalTransform(file, node, index);
    if (!isInvertible(world)) file.fail(at, "a node whose world transform is invertible");
    if (node.mesh >= 0) {
        const uint32_t mesh = convertMesh(node.mesh, at + "/mesh");
        if (!scene.meshes[mesh].triangles.empty()) scene.instances.push_back({mesh, world});
    }
    if (node.camera >= 0) addCamera(node.camera, world, node, at + "/camera");
    const auto lights = node.extensions.find("KHR_lights_punctual");
    if (lights != node.extensions.end()) {
        const std::string lightAt = at + "/extensions/KHR_lights_punctual/light";
        const tinygltf::Value& light = lights->second.Get("light");
        if (!light.IsInt()) file.fail(lightAt, "a light index");
        scene.lights.push_back(convertGltfLight(file, light.GetNumberAsInt(), world, lightAt));
    }
    for (size_t c = 0; c < node.children.size(); ++c) {
        const int child = node.children[c];
        if (child < 0 || static_cast<size_t>(child) >= model.nodes.size()) {
            file.fail(strCat(at, "/children/", c), "a node index");
        }
        visit(static_cast<size_t>(child), world, onPath);
    }
    onPath[index] = false;
}

tinygltf::Model readModel(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throwInputError(path, "", "a glTF file, cannot open it");
    }
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const bool ok = isGlbPath(path) ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                                    : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    if (!ok || !error.empty()) {
        throwInputError(path, "", "a valid glTF 2.0 file (" + flattenMessage(error) + ")");
    }
    return model;
}

// The root nodes to draw: the default scene's, else the first scene's, else every node that is
// no node's child.
std::vector<int> getRootNodes(const GltfFile& file) {
    const tinygltf::Model& model = file.model;
    if (!model.scenes.empty()) {
        const int s = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (static_cast<size_t>(s) >= model.scenes.size()) file.fail("/scene", "a scene index");
        return model.scenes[static_cast<size_t>(s)].nodes;
    }
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
        for (int c : node.children) {
            if (c >= 0 && static_cast<size_t>(c) < isChild.size())
                isChild[static_cast<size_t>(c)] = true;
        }
    }
    std::vector<int> roots;
    for (size_t i = 0; i < model.nodes.size(); ++i) {
        if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
}

} // namespace

bool isGltfPath(const std::string& path) {
    return getLowerExtension(path) == ".gltf" || isGlbPath(path);
}

std::vector<std::pair<std::string, Camera>>
importGltf(const std::string& path, const glm::mat4& worldFromFile, Scene& scene) {
    const tinygltf::Model model = readModel(path);
    const GltfFile file{model, path};
    const std::string prefix = std::filesystem::path(path).filename().string() + ":";
    GltfImporter importer{file, scene, prefix, importGltfMaterials(file, prefix, scene), {}, {}, 0};
    importer.sceneMeshes.resize(model.meshes.size());
    std::vector<bool> onPath(model.nodes.size(), false);
    const std::vector<int> roots = getRootNodes(file);
    for (size_t r = 0; r < roots.size(); ++r) {
        if (roots[r] < 0 || static_cast<size_t>(roots[r]) >= model.nodes.size()) {
            file.fail(strCat("/scenes/", std::max(model.defaultScene, 0), "/nodes/", r),
                      "a node index");
        }
        importer.visit(static_cast<size_t>(roots[r]), worldFromFile, onPath);
    }
    if (importer.triangleCount == 0) {
        file.fail("/meshes", "at least one triangle in the scene's nodes");
    }
    return importer.cameras;
}

Scene loadGltfScene(const std::string& path) {
    Scene scene;
    scene.sourcePath = path;
    scene.namedCameras = importGltf(path, glm::mat4(1.0f), scene);
    if (!scene.namedCameras.empty()) {
        scene.camera = scene.namedCameras.front().second;
        return scene;
    }
    // No camera: look along -z at the bounds' middle from where the bounding sphere fills the
    // default field of view.
    const Aabb bounds = scene.computeWorldBounds();
    const float radius = 0.5f * glm::length(bounds.getExtent());
    const float distance = radius / std::sin(glm::radians(0.5f * scene.camera.fovYDeg));
    scene.camera.target = bounds.getCenter();
    scene.camera.position = bounds.getCenter() + glm::vec3(0.0f, 0.0f, distance);
    return scene;
}

} // namespace ispm
