// The box city generator: a deterministic layout (our own PCG32, so the same seed gives the same
// city bit for bit on every standard library) turned into one mesh of boxes on a ground plane.
#include "scene/box_city.h"

#include "core/strings.h"
#include "scene/mesh_builder.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace ispm {

namespace {

// PCG32 (O'Neill, pcg-random.org, XSH RR 64/32): tiny, fast and fully specified, unlike the
// std:: distributions whose output differs between library versions.
class Pcg32 {
  public:
    explicit Pcg32(uint64_t seed) {
        next();
        mState += seed;
        next();
    }

    uint32_t next() {
        constexpr uint64_t kMultiplier = 6364136223846793005ull;
        constexpr uint64_t kIncrement = 1442695040888963407ull; // any odd number
        const uint64_t old = mState;
        mState = old * kMultiplier + kIncrement;
        const auto xorShifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rotation = static_cast<uint32_t>(old >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((0u - rotation) & 31u));
    }

    // [lo, hi]: 24 random bits fill a float's mantissa exactly.
    float uniform(float lo, float hi) {
        constexpr float kInv2Pow24 = 1.0f / 16777216.0f;
        const float u = static_cast<float>(next() >> 8u) * kInv2Pow24;
        return std::min(hi, lo + (hi - lo) * u);
    }

    // [lo, hi] by Lemire's multiply-shift; the bias (< 2^-32 per value) does not matter here.
    int uniformInt(int lo, int hi) {
        const auto range = static_cast<uint64_t>(static_cast<int64_t>(hi) - lo + 1);
        return lo + static_cast<int>((static_cast<uint64_t>(next()) * range) >> 32u);
    }

  private:
    uint64_t mState = 0;
};

// Attachments sink this fraction of their size into their building, so no attachment face is
// coplanar with a wall or roof (no z-fighting, no ambiguous ray hits).
constexpr float kAttachmentEmbed = 0.05f;
// Walls with less room than this to their lot's edge get no side attachments: they would barely
// show. Metres.
constexpr float kMinSideSetbackM = 0.25f;
// An even chance of a roof or a wall for each attachment (walls permitting).
constexpr float kRoofAttachmentChance = 0.5f;

constexpr uint32_t kPaletteSize = 4;
constexpr size_t kWallCount = 4; // a box building's sides: -x, +x, -z, +z

const std::array<Material, kPaletteSize>& getBuildingPalette() {
    static const std::array<Material, kPaletteSize> kPalette = [] {
        const std::array<glm::vec3, kPaletteSize> colours = {{
            {0.70f, 0.70f, 0.68f}, // light concrete
            {0.66f, 0.62f, 0.55f}, // sandstone
            {0.60f, 0.63f, 0.66f}, // blue-grey render
            {0.72f, 0.65f, 0.60f}, // warm plaster
        }};
        std::array<Material, kPaletteSize> palette;
        for (uint32_t i = 0; i < kPaletteSize; ++i) {
            palette[i].name = strCat("box_city_building_", i);
            palette[i].diffuse = colours[i];
        }
        return palette;
    }();
    return kPalette;
}

Material getGroundMaterial() {
    Material material;
    material.name = "box_city_ground";
    material.diffuse = {0.22f, 0.22f, 0.23f}; // asphalt-dark, so buildings stand out
    return material;
}

glm::vec2 computeLotSize(const BoxCityParams& p) {
    const glm::vec2 lots{p.lotsPerBlock};
    return (p.blockSizeM - (lots - 1.0f) * p.alleyWidthM) / lots;
}

// Places one attachment of the given size on the roof or a wall of `building`, inside its lot.
Aabb placeAttachment(Pcg32& rng, const Aabb& building,
                     const std::array<float, kWallCount>& setbacks, const glm::vec3& size,
                     bool& isOnRoof) {
    // Walls in setback order: -x, +x, -z, +z.
    std::array<int, kWallCount> walls{};
    int wallCount = 0;
    for (size_t w = 0; w < kWallCount; ++w) {
        if (setbacks[w] >= kMinSideSetbackM)
            walls[static_cast<size_t>(wallCount++)] = static_cast<int>(w);
    }
    isOnRoof = rng.uniform(0.0f, 1.0f) < kRoofAttachmentChance || wallCount == 0;
    const glm::vec3 lo = building.lo;
    const glm::vec3 hi = building.hi;
    Aabb box;
    if (isOnRoof) {
        const float cx = rng.uniform(lo.x + 0.5f * size.x, hi.x - 0.5f * size.x);
        const float cz = rng.uniform(lo.z + 0.5f * size.z, hi.z - 0.5f * size.z);
        const float y0 = hi.y - kAttachmentEmbed * size.y;
        box.lo = {cx - 0.5f * size.x, y0, cz - 0.5f * size.z};
        box.hi = {cx + 0.5f * size.x, y0 + size.y, cz + 0.5f * size.z};
        return box;
    }
    const int wall = walls[static_cast<size_t>(rng.uniformInt(0, wallCount - 1))];
    const int axis = wall < 2 ? 0 : 2;   // x or z
    const int along = axis == 0 ? 2 : 0; // the other horizontal axis
    const bool isPositive = (wall % 2) == 1;
    const float y0 = rng.uniform(0.0f, hi.y - size.y);
    const float c = rng.uniform(lo[along] + 0.5f * size[along], hi[along] - 0.5f * size[along]);
    const float protrusion =
        std::min(size[axis] * (1.0f - kAttachmentEmbed), setbacks[static_cast<size_t>(wall)]);
    box.lo.y = y0;
    box.hi.y = y0 + size.y;
    box.lo[along] = c - 0.5f * size[along];
    box.hi[along] = c + 0.5f * size[along];
    if (isPositive) {
        box.lo[axis] = hi[axis] - (size[axis] - protrusion);
        box.hi[axis] = hi[axis] + protrusion;
    } else {
        box.lo[axis] = lo[axis] - protrusion;
        box.hi[axis] = lo[axis] + (size[axis] - protrusion);
    }
    return box;
}

// The lot's building, set back from each lot edge, and its attachments.
void addBuilding(Pcg32& rng, const BoxCityParams& p, uint32_t lotIndex, BoxCityLayout& layout) {
    const Aabb& lot = layout.lots[lotIndex];
    std::array<float, kWallCount> setbacks{}; // -x, +x, -z, +z
    for (float& s : setbacks)
        s = rng.uniform(p.buildingInsetM.x, p.buildingInsetM.y);
    const float height = rng.uniform(p.buildingHeightM.x, p.buildingHeightM.y);
    const auto palette = static_cast<uint32_t>(rng.uniformInt(0, kPaletteSize - 1));

    const auto buildingIndex = static_cast<uint32_t>(layout.boxes.size());
    CityBox building{CityBoxKind::Building, {}, buildingIndex, lotIndex, palette};
    building.box.lo = {lot.lo.x + setbacks[0], 0.0f, lot.lo.z + setbacks[2]};
    building.box.hi = {lot.hi.x - setbacks[1], height, lot.hi.z - setbacks[3]};
    layout.boxes.push_back(building);

    const glm::vec3 extent = building.box.getExtent();
    const int count = rng.uniformInt(p.attachments.x, p.attachments.y);
    for (int a = 0; a < count; ++a) {
        glm::vec3 size;
        for (int i = 0; i < 3; ++i) {
            size[i] = extent[i] * rng.uniform(p.attachmentSize.x, p.attachmentSize.y);
        }
        bool isOnRoof = false;
        const Aabb box = placeAttachment(rng, building.box, setbacks, size, isOnRoof);
        layout.boxes.push_back(
            {isOnRoof ? CityBoxKind::RoofAttachment : CityBoxKind::SideAttachment, box,
             buildingIndex, lotIndex, palette});
    }
}

} // namespace

std::optional<BoxCityParamError> checkBoxCityParams(const BoxCityParams& p) {
    const auto isIn = [](int v, int lo, int hi) { return v >= lo && v <= hi; };
    if (!isIn(p.blocks.x, 1, kMaxCityBlocksPerAxis) ||
        !isIn(p.blocks.y, 1, kMaxCityBlocksPerAxis)) {
        return BoxCityParamError{"blocks",
                                 strCat("2 integers in [1, ", kMaxCityBlocksPerAxis, "]")};
    }
    if (!isIn(p.lotsPerBlock.x, 1, kMaxCityBlocksPerAxis) ||
        !isIn(p.lotsPerBlock.y, 1, kMaxCityBlocksPerAxis)) {
        return BoxCityParamError{"lots_per_block",
                                 strCat("2 integers in [1, ", kMaxCityBlocksPerAxis, "]")};
    }
    const int64_t buildings =
        int64_t{p.blocks.x} * p.blocks.y * p.lotsPerBlock.x * p.lotsPerBlock.y;
    if (buildings > kMaxCityBuildings) {
        return BoxCityParamError{"blocks",
                                 strCat("at most ", kMaxCityBuildings,
                                        " buildings (blocks x lots_per_block), got ", buildings)};
    }
    if (!(p.blockSizeM.x > 0.0f && p.blockSizeM.y > 0.0f)) {
        return BoxCityParamError{"block_size", "2 numbers > 0"};
    }
    if (!(p.streetWidthM >= 0.0f)) return BoxCityParamError{"street_width", "a number >= 0"};
    if (!(p.alleyWidthM >= 0.0f)) return BoxCityParamError{"alley_width", "a number >= 0"};
    const glm::vec2 lot = computeLotSize(p);
    if (!(lot.x > 0.0f && lot.y > 0.0f)) {
        return BoxCityParamError{"alley_width",
                                 strCat("alleys that leave lots of positive size, got lots of ",
                                        lot.x, " x ", lot.y, " m")};
    }
    const auto isRange = [](const glm::vec2& r) { return r.x <= r.y; };
    if (!(p.buildingHeightM.x > 0.0f) || !isRange(p.buildingHeightM)) {
        return BoxCityParamError{"building_height", "[min, max] with 0 < min <= max"};
    }
    if (!(p.buildingInsetM.x >= 0.0f) || !isRange(p.buildingInsetM)) {
        return BoxCityParamError{"building_inset", "[min, max] with 0 <= min <= max"};
    }
    if (!(2.0f * p.buildingInsetM.y < std::min(lot.x, lot.y))) {
        return BoxCityParamError{"building_inset",
                                 strCat("2 x max inset < the lot size (", lot.x, " x ", lot.y,
                                        " m), so every building has a footprint")};
    }
    if (p.attachments.x < 0 || p.attachments.x > p.attachments.y ||
        p.attachments.y > kMaxAttachmentsPerBuilding) {
        return BoxCityParamError{"attachments", strCat("[min, max] with 0 <= min <= max <= ",
                                                       kMaxAttachmentsPerBuilding)};
    }
    if (!(p.attachmentSize.x > 0.0f) || !isRange(p.attachmentSize) ||
        !(p.attachmentSize.y <= 1.0f)) {
        return BoxCityParamError{"attachment_size", "[min, max] with 0 < min <= max <= 1"};
    }
    return std::nullopt;
}

BoxCityLayout computeBoxCityLayout(const BoxCityParams& p) {
    if (const auto error = checkBoxCityParams(p)) {
        throw std::invalid_argument(
            strCat("box city: ", error->key, ": expected ", error->expected));
    }
    const glm::vec2 lotSize = computeLotSize(p);
    const glm::vec2 blocks{p.blocks};
    const glm::vec2 cityExtent = blocks * p.blockSizeM + (blocks - 1.0f) * p.streetWidthM;
    const glm::vec2 origin = -0.5f * cityExtent;

    BoxCityLayout layout;
    layout.groundBounds.lo = {origin.x - p.streetWidthM, 0.0f, origin.y - p.streetWidthM};
    layout.groundBounds.hi = {origin.x + cityExtent.x + p.streetWidthM, 0.0f,
                              origin.y + cityExtent.y + p.streetWidthM};
    layout.boxes.push_back({CityBoxKind::Ground, layout.groundBounds, 0, 0, 0});

    Pcg32 rng(p.seed);
    for (int bz = 0; bz < p.blocks.y; ++bz) {
        for (int bx = 0; bx < p.blocks.x; ++bx) {
            const glm::vec2 blockLo =
                origin + glm::vec2(bx, bz) * (p.blockSizeM + glm::vec2(p.streetWidthM));
            for (int lz = 0; lz < p.lotsPerBlock.y; ++lz) {
                for (int lx = 0; lx < p.lotsPerBlock.x; ++lx) {
                    const glm::vec2 lotLo =
                        blockLo + glm::vec2(lx, lz) * (lotSize + glm::vec2(p.alleyWidthM));
                    Aabb lot;
                    lot.lo = {lotLo.x, 0.0f, lotLo.y};
                    lot.hi = {lotLo.x + lotSize.x, 0.0f, lotLo.y + lotSize.y};
                    layout.lots.push_back(lot);
                    addBuilding(rng, p, static_cast<uint32_t>(layout.lots.size() - 1), layout);
                }
            }
        }
    }
    return layout;
}

void addBoxCity(Scene& scene, const BoxCityParams& params, const glm::mat4& worldFromObject) {
    const BoxCityLayout layout = computeBoxCityLayout(params);
    const auto checkIndex = [&scene](int32_t index) {
        if (index >= 0 && static_cast<size_t>(index) >= scene.materials.size()) {
            throw std::invalid_argument(
                strCat("box city: material index ", index, " out of range"));
        }
    };
    checkIndex(params.groundMaterial);
    checkIndex(params.buildingMaterial);

    const uint32_t ground = params.groundMaterial >= 0
                                ? static_cast<uint32_t>(params.groundMaterial)
                                : findOrAddMaterial(scene, getGroundMaterial());
    std::array<uint32_t, kPaletteSize> palette{};
    for (uint32_t i = 0; i < kPaletteSize; ++i) {
        palette[i] = params.buildingMaterial >= 0
                         ? static_cast<uint32_t>(params.buildingMaterial)
                         : findOrAddMaterial(scene, getBuildingPalette()[i]);
    }

    Mesh mesh;
    mesh.name = "box_city";
    for (const CityBox& b : layout.boxes) {
        if (b.kind == CityBoxKind::Ground) continue;
        // A box standing on the ground never shows its bottom face.
        const bool withBottom = b.box.lo.y > 0.0f;
        appendBox(mesh, b.box.lo, b.box.hi, palette[b.paletteIndex], withBottom);
    }
    // The ground last: every camera sees it behind buildings, and drawn after them the
    // rasteriser's early depth test rejects it there instead of shading it under each one.
    const glm::vec3 lo = layout.groundBounds.lo;
    const glm::vec3 hi = layout.groundBounds.hi;
    appendQuad(mesh, {lo.x, 0.0f, lo.z}, {lo.x, 0.0f, hi.z}, {hi.x, 0.0f, hi.z}, {hi.x, 0.0f, lo.z},
               ground);
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({static_cast<uint32_t>(scene.meshes.size() - 1), worldFromObject});
}

} // namespace ispm
