// Per-vertex tangents from positions and texture coordinates (mesh_tangents.h).
#include "scene/mesh_tangents.h"

#include <array>
#include <cmath>

namespace ispm {

namespace {

// |du1 dv2 - du2 dv1| below this: the triangle's texture coordinates are (nearly) collinear and
// give no direction (texture coordinates are of order 1).
constexpr float kMinUvArea = 1e-12f;

glm::vec3 normalizeOrZero(glm::vec3 v) {
    const float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0.0f);
}

// The angle between two edges leaving a corner (0 for a degenerate edge).
float computeCornerAngle(glm::vec3 a, glm::vec3 b) {
    const glm::vec3 ua = normalizeOrZero(a);
    const glm::vec3 ub = normalizeOrZero(b);
    if (ua == glm::vec3(0.0f) || ub == glm::vec3(0.0f)) return 0.0f;
    return std::acos(glm::clamp(glm::dot(ua, ub), -1.0f, 1.0f));
}

} // namespace

std::vector<glm::vec4> computeVertexTangents(std::span<const glm::vec3> positions,
                                             std::span<const glm::vec2> texcoords,
                                             std::span<const glm::vec3> normals,
                                             std::span<const glm::uvec3> triangles) {
    const size_t count = positions.size();
    std::vector<glm::vec3> alongU(count, glm::vec3(0.0f));
    std::vector<glm::vec3> upImage(count, glm::vec3(0.0f)); // along -v
    std::vector<glm::vec3> faceNormals(count, glm::vec3(0.0f));
    for (const glm::uvec3& t : triangles) {
        const std::array<glm::vec3, 3> p = {positions[t.x], positions[t.y], positions[t.z]};
        const std::array<glm::vec2, 3> uv = {texcoords[t.x], texcoords[t.y], texcoords[t.z]};
        const glm::vec3 e1 = p[1] - p[0];
        const glm::vec3 e2 = p[2] - p[0];
        const glm::vec2 d1 = uv[1] - uv[0];
        const glm::vec2 d2 = uv[2] - uv[0];
        const float det = d1.x * d2.y - d2.x * d1.y;
        const bool hasUv = std::abs(det) > kMinUvArea;
        // Solving e1 = d1.x dP/du + d1.y dP/dv, e2 = d2.x dP/du + d2.y dP/dv.
        const glm::vec3 dPdu =
            hasUv ? normalizeOrZero((d2.y * e1 - d1.y * e2) / det) : glm::vec3(0);
        const glm::vec3 dPdv =
            hasUv ? normalizeOrZero((d1.x * e2 - d2.x * e1) / det) : glm::vec3(0);
        const glm::vec3 face = normalizeOrZero(glm::cross(e1, e2));
        for (int k = 0; k < 3; ++k) {
            const size_t v = t[k];
            const float angle = computeCornerAngle(p[size_t(k + 1) % 3] - p[size_t(k)],
                                                   p[size_t(k + 2) % 3] - p[size_t(k)]);
            alongU[v] += angle * dPdu;
            upImage[v] -= angle * dPdv;
            faceNormals[v] += angle * face;
        }
    }
    std::vector<glm::vec4> tangents(count, glm::vec4(0.0f));
    for (size_t v = 0; v < count; ++v) {
        glm::vec3 n = v < normals.size() ? normalizeOrZero(normals[v]) : glm::vec3(0.0f);
        if (n == glm::vec3(0.0f)) n = normalizeOrZero(faceNormals[v]);
        const glm::vec3 t = normalizeOrZero(alongU[v] - glm::dot(n, alongU[v]) * n);
        if (n == glm::vec3(0.0f) || t == glm::vec3(0.0f)) continue;
        const float w = glm::dot(glm::cross(n, t), upImage[v]) < 0.0f ? -1.0f : 1.0f;
        tangents[v] = glm::vec4(t, w);
    }
    return tangents;
}

} // namespace ispm
