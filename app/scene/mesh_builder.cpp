// Mesh building blocks: triangles, quads and boxes appended with their material indices.
#include "scene/mesh_builder.h"

#include <algorithm>
#include <array>

namespace ispm {

bool isDegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    // |e1 x e2| = |e1| |e2| sin(angle): compared with the longest squared edge it bounds the
    // smallest angle's sine, independent of scale. Float cross products are good to ~1e-7.
    constexpr float kMinSine = 1e-6f;
    const glm::vec3 e1 = b - a;
    const glm::vec3 e2 = c - a;
    const glm::vec3 e3 = c - b;
    const float longest2 = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
    const float twiceArea = glm::length(glm::cross(e1, e2));
    return !(twiceArea > kMinSine * longest2);
}

void appendTriangle(Mesh& mesh, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                    uint32_t material) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.triangles.emplace_back(base, base + 1, base + 2);
    mesh.triangleMaterials.push_back(material);
}

void appendQuad(Mesh& mesh, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                const glm::vec3& p3, uint32_t material) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {p0, p1, p2, p3});
    mesh.triangles.emplace_back(base, base + 1, base + 2);
    mesh.triangles.emplace_back(base, base + 2, base + 3);
    mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {material, material});
}

void appendBox(Mesh& mesh, const glm::vec3& lo, const glm::vec3& hi, uint32_t material,
               bool withBottom) {
    // Corner i has x from bit 0, y from bit 1, z from bit 2 (0: lo, 1: hi).
    constexpr int kCornerCount = 8;
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (int i = 0; i < kCornerCount; ++i) {
        mesh.positions.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                    (i & 4) ? hi.z : lo.z);
    }
    // Each face's corners counter-clockwise seen from outside; the bottom (-y) face is last.
    constexpr std::array<std::array<uint32_t, 4>, 6> kFaces = {{
        {0, 4, 6, 2}, // -x
        {1, 3, 7, 5}, // +x
        {2, 6, 7, 3}, // +y
        {0, 2, 3, 1}, // -z
        {4, 5, 7, 6}, // +z
        {0, 1, 5, 4}, // -y
    }};
    const size_t faceCount = withBottom ? kFaces.size() : kFaces.size() - 1;
    for (size_t f = 0; f < faceCount; ++f) {
        const std::array<uint32_t, 4>& q = kFaces[f];
        mesh.triangles.emplace_back(base + q[0], base + q[1], base + q[2]);
        mesh.triangles.emplace_back(base + q[0], base + q[2], base + q[3]);
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {material, material});
    }
}

uint32_t findOrAddMaterial(Scene& scene, const Material& material) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].name == material.name) return static_cast<uint32_t>(i);
    }
    scene.materials.push_back(material);
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

} // namespace ispm
