// Small building blocks shared by the loader and the generators: appending triangles, quads and
// boxes to a mesh, the zero-area test, and finding or adding a material by name.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace ispm {

// True when the triangle has (numerically) zero area: its smallest angle's sine is below about
// 1e-6, so collinear and repeated points are caught whatever the triangle's size.
bool isDegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

void appendTriangle(Mesh& mesh, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                    uint32_t material);
// Split as (0,1,2), (0,2,3), as the scene format documents.
void appendQuad(Mesh& mesh, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                const glm::vec3& p3, uint32_t material);
// An axis-aligned box with outward (counter-clockwise) faces: 12 triangles, or 10 without the
// bottom face (for boxes standing on a ground plane, where that face could never be seen).
void appendBox(Mesh& mesh, const glm::vec3& lo, const glm::vec3& hi, uint32_t material,
               bool withBottom = true);

// The index of the scene's material with this name, adding `material` when there is none. A
// scene file may so define a generator's materials (e.g. "cornell_white") to override them.
uint32_t findOrAddMaterial(Scene& scene, const Material& material);

} // namespace ispm
