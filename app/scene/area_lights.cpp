// The `area` light of scene files: a rectangle or disc of emitting triangles (an emissive mesh,
// docs/scene-format.md "Lights"), its radiance given or derived from its power.
#include "core/strings.h"
#include "scene/scene_parse.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace ispm {

namespace {

constexpr double kMaxAreaRadiance = 1e12; // as materials' emission
constexpr int kDiscSegments = 48;         // the disc's polygon: 0.3% less area, exact power

// Unit vectors across the emitter: `tangent` along its first size, the other completing a
// right-handed frame with `normal` (the side it emits to).
void buildFrame(const glm::vec3& normal, const glm::vec3& tangentHint, glm::vec3& t, glm::vec3& b) {
    t = glm::normalize(tangentHint - normal * glm::dot(tangentHint, normal));
    b = glm::cross(normal, t);
}

} // namespace

void parseAreaLight(const JsonNode& node, size_t index, ParseContext& context) {
    node.checkKeys({"type", "name", "shape", "position", "normal", "tangent", "size", "radius",
                    "radiance", "power", "two_sided", "photon_share"},
                   "an area light");
    Scene& scene = context.scene;
    const std::string name =
        node.has("name") ? node.get("name").readString() : strCat("area_light_", index);
    const std::string shape = node.has("shape") ? node.get("shape").readString() : "rect";
    if (shape != "rect" && shape != "disc") node.get("shape").failGot("a shape: rect or disc");
    const glm::vec3 centre = node.get("position").readVec3();
    const glm::vec3 normal = node.get("normal").readDirection();
    // The default tangent: x for a horizontal emitter, else the horizontal across it.
    glm::vec3 hint = std::abs(normal.y) > 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f)
                                               : glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), normal);
    if (auto tangent = node.find("tangent")) {
        hint = tangent->readDirection();
        if (!(glm::length(glm::cross(hint, normal)) > 1e-4f)) {
            tangent->fail("a tangent not parallel to the normal");
        }
    }
    glm::vec3 t;
    glm::vec3 b;
    buildFrame(normal, hint, t, b);
    const NumberRange extent = NumberRange::getLeftOpen(0.0, 1e7);
    Mesh mesh;
    mesh.name = name;
    if (shape == "rect") {
        if (node.has("radius")) node.get("radius").fail("no radius on a rect (size: [w, h])");
        const glm::vec2 size = node.get("size").readVec2(extent);
        const glm::vec3 u = t * (0.5f * size.x);
        const glm::vec3 v = b * (0.5f * size.y);
        mesh.positions = {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
        mesh.triangles = {{0, 1, 2}, {0, 2, 3}}; // counter-clockwise about the normal
    } else {
        if (node.has("size")) node.get("size").fail("no size on a disc (radius: metres)");
        const float radius = node.get("radius").readFloat(extent);
        mesh.positions.push_back(centre);
        for (int i = 0; i < kDiscSegments; ++i) {
            const float a = glm::two_pi<float>() * float(i) / float(kDiscSegments);
            mesh.positions.push_back(centre + radius * (std::cos(a) * t + std::sin(a) * b));
        }
        for (uint32_t i = 0; i < uint32_t(kDiscSegments); ++i)
            mesh.triangles.push_back({0u, 1u + i, 1u + (i + 1u) % uint32_t(kDiscSegments)});
    }
    double areaM2 = 0.0;
    for (const glm::uvec3& tri : mesh.triangles) {
        const glm::vec3 p0 = mesh.positions[tri.x];
        areaM2 += 0.5 * glm::length(glm::dvec3(
                            glm::cross(mesh.positions[tri.y] - p0, mesh.positions[tri.z] - p0)));
    }
    Material material;
    material.name = name;
    if (auto two = node.find("two_sided")) material.emissionTwoSided = two->readBool();
    const bool hasRadiance = node.has("radiance");
    if (hasRadiance == node.has("power")) {
        node.fail("an area light with one of radiance (W/(m^2 sr)) or power (W)");
    }
    if (hasRadiance) {
        material.emission =
            node.get("radiance").readVec3(NumberRange::getClosed(0.0, kMaxAreaRadiance));
    } else {
        const JsonNode powerNode = node.get("power");
        const glm::vec3 power = powerNode.readVec3(NumberRange::getClosed(0.0, 1e12));
        // Power = pi x radiance x area x sides (a Lambertian emitter).
        const double sides = material.emissionTwoSided ? 2.0 : 1.0;
        const glm::dvec3 radiance = glm::dvec3(power) / (glm::pi<double>() * areaM2 * sides);
        if (!(radiance.x <= kMaxAreaRadiance && radiance.y <= kMaxAreaRadiance &&
              radiance.z <= kMaxAreaRadiance)) {
            powerNode.fail(strCat("a power of at most ", formatFloat(float(kMaxAreaRadiance)),
                                  " W/(m^2 sr) over the light's area"));
        }
        material.emission = glm::vec3(radiance);
    }
    if (auto share = node.find("photon_share")) {
        material.photonShare = share->readFloat(NumberRange::getClosed(0.0, 1.0));
    }
    mesh.triangleMaterials.assign(mesh.triangles.size(), uint32_t(scene.materials.size()));
    scene.materials.push_back(material);
    scene.instances.push_back({uint32_t(scene.meshes.size()), glm::mat4(1.0f)});
    scene.meshes.push_back(std::move(mesh));
}

} // namespace ispm
