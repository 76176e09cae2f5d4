// Emissive triangles as lights: every triangle whose material emits, in world space, grouped by
// material (a group's photons count as one light's in reports and budgets), with the power each
// sends out (docs/design.md "Emitters"). Plain data; GpuScene uploads it as GpuEmitter rows.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ispm {

struct EmitterTriangle {
    glm::vec3 p0{0.0f};
    glm::vec3 p1{0.0f};
    glm::vec3 p2{0.0f};
    glm::vec3 radiance{0.0f}; // W/(m^2 sr) on the side the winding faces (both: twoSided)
    bool twoSided = false;
    double areaM2 = 0.0;
    double weight = 0.0; // mean(radiance) x area x pi x sides: the power it sends out (W)
};

// The emitting triangles of one material, contiguous in Emitters::triangles.
struct EmitterGroup {
    uint32_t material = 0;
    uint32_t first = 0;
    uint32_t count = 0;
    double weight = 0.0;          // the sum of its triangles' (W)
    glm::dvec3 powerW{0.0};       // per channel (W)
    double luminancePowerW = 0.0; // Rec. 709 luminance of powerW, for photon shares
    float photonShare = -1.0f;    // the material's (< 0: derived from the power)
};

struct Emitters {
    std::vector<EmitterTriangle> triangles; // by group, in material order
    std::vector<EmitterGroup> groups;
    double totalWeight = 0.0;
    bool isEmpty() const { return triangles.empty(); }
};

// The scene's emitting triangles as placed now (Scene::update moves them with their instances).
// Triangles of zero area (or whose area is not finite) are left out.
Emitters collectEmitters(const Scene& scene);

// "ispm: warning:" text naming the meshes whose emitting triangles have no area and are left out
// (empty when none).
std::string describeDroppedEmitters(const Scene& scene);

} // namespace ispm
