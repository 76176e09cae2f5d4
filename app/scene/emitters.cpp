// Emitting triangles, collected per material in world space.
#include "scene/emitters.h"

#include "core/strings.h"

#include <shared/emitter_data.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <set>

namespace ispm {
namespace {

bool isEmitting(const Material& m) {
    return m.emission != glm::vec3(0.0f);
}

double computeLuminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; // Rec. 709, as photon shares weigh lights
}

} // namespace

Emitters collectEmitters(const Scene& scene) {
    Emitters emitters;
    std::vector<bool> emits(scene.materials.size());
    bool any = false;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        emits[m] = isEmitting(scene.materials[m]);
        any = any || emits[m];
    }
    if (!any) return emitters;
    // One pass per emitting material keeps each group contiguous, in material order.
    for (uint32_t material = 0; material < scene.materials.size(); ++material) {
        if (!emits[material]) continue;
        const Material& mat = scene.materials[material];
        EmitterGroup group;
        group.material = material;
        group.first = uint32_t(emitters.triangles.size());
        group.photonShare = mat.photonShare;
        const double sides = mat.emissionTwoSided ? 2.0 : 1.0;
        for (const Instance& instance : scene.instances) {
            const Mesh& mesh = scene.meshes[instance.meshIndex];
            for (size_t t = 0; t < mesh.triangles.size(); ++t) {
                if (mesh.triangleMaterials[t] != material) continue;
                const glm::uvec3 tri = mesh.triangles[t];
                EmitterTriangle e;
                const auto place = [&](uint32_t i) {
                    return glm::vec3(instance.worldFromObject * glm::vec4(mesh.positions[i], 1.0f));
                };
                e.p0 = place(tri.x);
                e.p1 = place(tri.y);
                e.p2 = place(tri.z);
                e.areaM2 = 0.5 * glm::length(glm::dvec3(glm::cross(e.p1 - e.p0, e.p2 - e.p0)));
                if (!(e.areaM2 > 0.0) || !std::isfinite(e.areaM2)) continue;
                e.radiance = mat.emission;
                e.twoSided = mat.emissionTwoSided;
                e.weight =
                    double(gpu::computeEmitterWeightPerArea(mat.emission, sides > 1.0)) * e.areaM2;
                group.weight += e.weight;
                group.powerW += glm::dvec3(mat.emission) * (e.areaM2 * glm::pi<double>() * sides);
                emitters.triangles.push_back(e);
            }
        }
        group.count = uint32_t(emitters.triangles.size()) - group.first;
        if (group.count == 0) continue;
        group.luminancePowerW = computeLuminance(group.powerW);
        emitters.totalWeight += group.weight;
        emitters.groups.push_back(group);
    }
    return emitters;
}

std::string describeDroppedEmitters(const Scene& scene) {
    std::set<std::string> names;
    for (const Instance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes[instance.meshIndex];
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const Material& m = scene.materials[mesh.triangleMaterials[t]];
            if (!isEmitting(m)) continue;
            const glm::uvec3 tri = mesh.triangles[t];
            const auto place = [&](uint32_t i) {
                return glm::vec3(instance.worldFromObject * glm::vec4(mesh.positions[i], 1.0f));
            };
            const glm::vec3 p0 = place(tri.x);
            const double area =
                0.5 * glm::length(glm::dvec3(glm::cross(place(tri.y) - p0, place(tri.z) - p0)));
            if (!(area > 0.0) || !std::isfinite(area)) {
                names.insert(strCat("mesh '", mesh.name, "' (material '", m.name, "')"));
            }
        }
    }
    if (names.empty()) return "";
    std::string list;
    for (const std::string& name : names)
        list += (list.empty() ? "" : ", ") + name;
    return strCat("emitting triangles of zero area left out (they emit no light): ", list);
}

} // namespace ispm
