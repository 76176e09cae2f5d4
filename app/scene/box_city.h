// The `box_city` generator (McLaughlin's thesis): a grid of city blocks separated by streets,
// each block split by narrower back alleys into lots, one box building per lot set back from the
// lot's edges, smaller random boxes attached to roofs and walls, and a ground plane under it all.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ispm {

// Defaults give a 4 x 4 block city about 250 m across with 64 buildings and ~1,800 triangles.
struct BoxCityParams {
    glm::ivec2 blocks{4, 4};                // blocks along x and z
    glm::vec2 blockSizeM{48.0f, 48.0f};     // x, z
    float streetWidthM = 12.0f;             // between blocks, and the ground's margin around
    float alleyWidthM = 4.0f;               // between lots inside a block
    glm::ivec2 lotsPerBlock{2, 2};          // x, z
    glm::vec2 buildingHeightM{8.0f, 40.0f}; // [min, max]
    glm::vec2 buildingInsetM{1.0f, 3.0f};   // [min, max] setback from each lot edge
    glm::ivec2 attachments{0, 3};           // [min, max] boxes per building
    glm::vec2 attachmentSize{0.2f, 0.5f};   // [min, max] fraction of the building, per axis
    uint64_t seed = 1;
    int32_t buildingMaterial = -1; // index into Scene::materials; < 0: the default palette
    int32_t groundMaterial = -1;   // index into Scene::materials; < 0: the default asphalt
};

inline constexpr int kMaxCityBuildings = 10000; // blocks x lots; keeps generation interactive
inline constexpr int kMaxAttachmentsPerBuilding = 16;
inline constexpr int kMaxCityBlocksPerAxis = 1000; // bounds blocks before their product is taken

// The first parameter that breaks a constraint: its scene-file key and what was expected.
struct BoxCityParamError {
    std::string key;
    std::string expected;
};
std::optional<BoxCityParamError> checkBoxCityParams(const BoxCityParams& params);

enum class CityBoxKind { Ground, Building, RoofAttachment, SideAttachment };

// One box of the layout, in the city's object space (y up, ground at y = 0, centred on x = z = 0).
struct CityBox {
    CityBoxKind kind = CityBoxKind::Building;
    Aabb box;              // the ground has lo.y == hi.y == 0
    uint32_t building = 0; // attachments: the index of their building in the layout's boxes
    uint32_t lot = 0;      // buildings and attachments: index into BoxCityLayout::lots
    uint32_t paletteIndex = 0;
};

struct BoxCityLayout {
    std::vector<CityBox> boxes; // the ground first, then each building followed by its attachments
    std::vector<Aabb> lots;     // footprints, y = 0
    Aabb groundBounds;          // the ground plane: the city plus one street width around it
};

// The layout alone (no scene): the same parameters always give bit-identical boxes. Throws
// std::invalid_argument when checkBoxCityParams finds a problem.
BoxCityLayout computeBoxCityLayout(const BoxCityParams& params);

// Appends the city as one mesh and one instance. Default materials are named box_city_ground and
// box_city_building_0..3; ones the scene already has under those names are used instead.
void addBoxCity(Scene& scene, const BoxCityParams& params, const glm::mat4& worldFromObject);

} // namespace ispm
