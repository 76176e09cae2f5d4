// Smooth shading normals from the faces of a mesh, split at creases sharper than a threshold.
#include "scene/mesh_normals.h"

#include <glm/gtc/constants.hpp>

#include <cassert>
#include <cmath>
#include <cstring>
#include <map>
#include <vector>

namespace ispm {

namespace {

// The corner's interior angle (radians): the weight of its face at that corner (Thürmer and
// Wüthrich 1998), which, unlike area weighting, does not change when a face is split in two.
float computeCornerAngle(const glm::vec3& at, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 u = a - at;
    const glm::vec3 v = b - at;
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

// A position's bits, so equal positions match exactly however they were listed.
struct PositionKey {
    uint32_t bits[3];
    bool operator<(const PositionKey& o) const {
        return std::memcmp(bits, o.bits, sizeof(bits)) < 0;
    }
};

PositionKey makeKey(const glm::vec3& p) {
    // -0 and +0 are one position.
    const glm::vec3 q = p + glm::vec3(0.0f);
    PositionKey key;
    std::memcpy(key.bits, &q[0], sizeof(key.bits));
    return key;
}

} // namespace

void generateSmoothNormals(Mesh& mesh, float maxAngleDeg) {
    assert(maxAngleDeg > 0.0f && maxAngleDeg <= 180.0f);
    const size_t triangleCount = mesh.triangles.size();
    std::vector<glm::vec3> faceNormals(triangleCount);
    std::vector<glm::vec3> cornerAngles(triangleCount);
    // The corners (triangle * 3 + k) at each distinct position.
    std::map<PositionKey, std::vector<uint32_t>> cornersAt;
    for (size_t t = 0; t < triangleCount; ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        const glm::vec3 p[3] = {mesh.positions[tri.x], mesh.positions[tri.y],
                                mesh.positions[tri.z]};
        faceNormals[t] = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        for (int k = 0; k < 3; ++k) {
            cornerAngles[t][k] = computeCornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
            cornersAt[makeKey(p[k])].push_back(static_cast<uint32_t>(3 * t + size_t(k)));
        }
    }
    // A small margin keeps faces exactly at the threshold (a cube's 90 degrees at 90) smooth
    // despite the round-off of their normals.
    constexpr float kCosMargin = 1e-6f;
    const float minCos = std::cos(glm::radians(maxAngleDeg)) - kCosMargin;
    std::vector<glm::vec3> cornerNormals(3 * triangleCount);
    for (const auto& [key, corners] : cornersAt) {
        for (const uint32_t c : corners) {
            const glm::vec3 own = faceNormals[c / 3];
            glm::vec3 sum(0.0f);
            for (const uint32_t o : corners) {
                const glm::vec3 other = faceNormals[o / 3];
                if (glm::dot(own, other) >= minCos) sum += cornerAngles[o / 3][o % 3] * other;
            }
            // Faces that cancel (a sheet folded back on itself) keep the corner's own normal.
            const float length = glm::length(sum);
            cornerNormals[c] = length > 0.0f && std::isfinite(length) ? sum / length : own;
        }
    }
    // One vertex per (old vertex, normal): corners that agree share it.
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> texcoords;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents;
    std::map<std::pair<uint32_t, PositionKey>, uint32_t> vertexOf;
    for (size_t t = 0; t < triangleCount; ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t old = mesh.triangles[t][k];
            const glm::vec3 n = cornerNormals[3 * t + size_t(k)];
            const auto [it, added] =
                vertexOf.try_emplace({old, makeKey(n)}, static_cast<uint32_t>(positions.size()));
            if (added) {
                positions.push_back(mesh.positions[old]);
                if (!mesh.texcoords.empty()) texcoords.push_back(mesh.texcoords[old]);
                if (!mesh.tangents.empty()) tangents.push_back(mesh.tangents[old]);
                normals.push_back(n);
            }
            mesh.triangles[t][k] = it->second;
        }
    }
    mesh.positions = std::move(positions);
    mesh.texcoords = std::move(texcoords);
    mesh.normals = std::move(normals);
    mesh.tangents = std::move(tangents);
}

} // namespace ispm
