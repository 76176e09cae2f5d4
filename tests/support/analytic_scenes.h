// Scenes with closed-form answers, shared by the analytic tests: a diffuse ground plane under a
// point light, and where a camera ray through an image position meets that plane; and grey
// squares placed at will, without lights.
#pragma once

#include "scene/scene.h"

#include <span>

namespace ispm::test {

// The plane y = 0 (two triangles, half-size halfSizeM), diffuse reflectance rho, under a point
// light of intensity I (W/sr) at (0, heightM, 0). Camera left at its defaults.
Scene makeLitPlane(float rho, float intensity, float heightM, float halfSizeM);

// One grey (diffuse 0.5) 2 m square facing +z, centred on the origin, instanced once per
// transform. No lights; camera left at its defaults.
Scene makeGreySquares(std::span<const glm::mat4> worldFromSquare);

// Adds the 12 triangles of the box [lo, hi] to `mesh` (its faces two-sided, as every surface),
// material 0.
void addBox(Mesh& mesh, const glm::vec3& lo, const glm::vec3& hi);

// The camera ray through image position (px, py), in pixels with (0, 0) at the image's top-left
// corner (pixel centres at +0.5), as the renderer's camera math casts it: from the near plane,
// `dir` reaching the far plane at t = 1.
struct ViewRay {
    glm::dvec3 origin;
    glm::dvec3 dir;
};
ViewRay computeViewRay(const Scene& scene, int width, int height, double px, double py);

// Where the camera ray through image position (px, py) meets y = 0.
glm::dvec3 projectToGround(const Scene& scene, int width, int height, double px, double py);

// Radiance of a diffuse plane under a point light: rho / pi * I * h / d^3.
double computePlaneRadiance(float rho, float intensity, float heightM, const glm::dvec3& point);

} // namespace ispm::test
