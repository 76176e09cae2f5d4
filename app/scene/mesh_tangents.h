// Tangent frames for normal maps where a mesh gives none (glTF without TANGENT): per-vertex
// tangents from the positions and texture coordinates (docs/design.md "Normal maps").
#pragma once

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace ispm {

// Per vertex: the unit tangent along +u in xyz and the handedness in w (+-1), so that
// w cross(n, tangent) runs up the image (-v; texture coordinates have v down, as glTF's): glTF's
// TANGENT convention. Each triangle's dP/du and dP/dv (from its edges and their texture
// coordinate differences), normalised, add at its corners weighted by the corner's angle; the
// tangent is the sum made perpendicular to the vertex's normal (Gram-Schmidt), and w the sign of
// the summed -dP/dv along cross(n, tangent). `normals` may be empty, or zero at a vertex: then
// the angle-weighted face normals stand in. A vertex that no triangle with distinct texture
// coordinates touches gets w = 0 (no frame; the normal map does not act there).
std::vector<glm::vec4> computeVertexTangents(std::span<const glm::vec3> positions,
                                             std::span<const glm::vec2> texcoords,
                                             std::span<const glm::vec3> normals,
                                             std::span<const glm::uvec3> triangles);

} // namespace ispm
