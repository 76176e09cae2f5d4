// Closed-form scenes for analytic tests.
#include "support/analytic_scenes.h"

#include "render/frame.h"

#include <glm/gtc/constants.hpp>

namespace ispm::test {

Scene makeLitPlane(float rho, float intensity, float heightM, float halfSizeM) {
    Scene scene;
    scene.sourcePath = "analytic plane";
    Material m;
    m.name = "plane";
    m.diffuse = glm::vec3(rho);
    scene.materials.push_back(m);
    Mesh mesh;
    mesh.name = "plane";
    const float s = halfSizeM;
    mesh.positions = {{-s, 0, -s}, {s, 0, -s}, {s, 0, s}, {-s, 0, s}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.triangleMaterials = {0, 0};
    scene.meshes.push_back(mesh);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    Light light;
    light.type = LightType::Point;
    light.position = {0.0f, heightM, 0.0f};
    light.intensity = glm::vec3(intensity);
    scene.lights.push_back(light);
    return scene;
}

Scene makeGreySquares(std::span<const glm::mat4> worldFromSquare) {
    Scene scene;
    scene.sourcePath = "grey squares";
    Material grey;
    grey.name = "grey";
    grey.diffuse = glm::vec3(0.5f);
    scene.materials.push_back(grey);
    Mesh square;
    square.name = "square";
    square.positions = {
        {-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    square.triangleMaterials = {0, 0};
    scene.meshes.push_back(square);
    for (const glm::mat4& m : worldFromSquare)
        scene.instances.push_back({0, m});
    return scene;
}

void addBox(Mesh& mesh, const glm::vec3& lo, const glm::vec3& hi) {
    const uint32_t first = uint32_t(mesh.positions.size());
    for (int i = 0; i < kAabbCornerCount; ++i) {
        mesh.positions.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                    (i & 4) ? hi.z : lo.z);
    }
    const glm::uvec4 faces[6] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const glm::uvec4& f : faces) {
        mesh.triangles.emplace_back(first + f.x, first + f.y, first + f.z);
        mesh.triangles.emplace_back(first + f.x, first + f.z, first + f.w);
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {0u, 0u});
    }
}

ViewRay computeViewRay(const Scene& scene, int width, int height, double px, double py) {
    float nearM = 0.0f;
    float farM = 0.0f;
    computeCameraRange(scene.camera, scene.computeWorldBounds(), scene.computeInstanceBounds(),
                       nearM, farM);
    const float aspect = float(width) / float(height);
    const glm::dmat4 worldFromClip =
        glm::inverse(glm::dmat4(computeClipFromView(scene.camera, aspect, nearM, farM) *
                                computeViewFromWorld(scene.camera)));
    const glm::dvec2 ndc(px / width * 2.0 - 1.0, 1.0 - py / height * 2.0);
    const glm::dvec4 a = worldFromClip * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 b = worldFromClip * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 p0 = glm::dvec3(a) / a.w;
    const glm::dvec3 p1 = glm::dvec3(b) / b.w;
    return {p0, p1 - p0};
}

glm::dvec3 projectToGround(const Scene& scene, int width, int height, double px, double py) {
    const ViewRay ray = computeViewRay(scene, width, height, px, py);
    return ray.origin + ray.dir * (ray.origin.y / -ray.dir.y);
}

double computePlaneRadiance(float rho, float intensity, float heightM, const glm::dvec3& point) {
    const double d = glm::length(glm::dvec3(0.0, heightM, 0.0) - point);
    return double(rho) / glm::pi<double>() * double(intensity) * double(heightM) / (d * d * d);
}

} // namespace ispm::test
