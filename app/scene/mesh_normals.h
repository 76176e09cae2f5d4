// Smooth shading normals generated from a mesh's faces, as modelling tools import a mesh that
// has none (Blender's auto smooth, 3ds Max's smoothing angle).
#pragma once

#include "scene/scene.h"

namespace ispm {

// Gives `mesh` a unit normal at every triangle corner: the angle-weighted mean of the face
// normals of the triangles that share the corner's position and whose faces turn by at most
// `maxAngleDeg` from the corner's own (so a cube keeps its edges at 30 degrees and a
// tessellated sphere turns smooth). Positions are matched by value, so separately listed
// triangles (the scene format's `triangles`, `quads`) join; a position whose corners end up
// with different normals is split into one vertex per normal, texture coordinates kept.
// Normals the mesh already has are replaced. maxAngleDeg in (0, 180].
void generateSmoothNormals(Mesh& mesh, float maxAngleDeg);

} // namespace ispm
