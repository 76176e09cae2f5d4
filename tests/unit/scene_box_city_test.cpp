// The box city generator: determinism (same seed, same bytes), and every box of a layout within
// the declared ranges and inside its lot and the city, over several seeds and parameter sets.
#include "scene/box_city.h"
#include "scene_test_util.h"

#include <cstring>

namespace ispm::test {
namespace {

// Float slack for positions computed as sums of a few floats of ~100 m.
constexpr float kPositionSlackM = 1e-3f;
// Relative slack for ratios of such sizes.
constexpr float kRatioSlack = 1e-4f;

Scene buildCity(const BoxCityParams& params) {
    Scene scene;
    addBoxCity(scene, params, glm::mat4(1.0f));
    return scene;
}

bool haveSameBytes(const Mesh& a, const Mesh& b) {
    return a.positions.size() == b.positions.size() && a.triangles.size() == b.triangles.size() &&
           std::memcmp(a.positions.data(), b.positions.data(),
                       a.positions.size() * sizeof(glm::vec3)) == 0 &&
           std::memcmp(a.triangles.data(), b.triangles.data(),
                       a.triangles.size() * sizeof(glm::uvec3)) == 0 &&
           a.triangleMaterials == b.triangleMaterials;
}

TEST(BoxCity, SameSeedGivesIdenticalBytes) {
    BoxCityParams params;
    params.seed = 42;
    const Scene a = buildCity(params);
    const Scene b = buildCity(params);
    ASSERT_EQ(a.meshes.size(), 1u);
    EXPECT_TRUE(haveSameBytes(a.meshes[0], b.meshes[0]));
}

TEST(BoxCity, DifferentSeedGivesDifferentCity) {
    BoxCityParams params;
    params.seed = 42;
    const Scene a = buildCity(params);
    params.seed = 43;
    const Scene b = buildCity(params);
    EXPECT_FALSE(haveSameBytes(a.meshes[0], b.meshes[0]));
}

TEST(BoxCity, DefaultsGiveAModestCity) {
    const Scene scene = buildCity(BoxCityParams{});
    const glm::vec3 extent = scene.computeWorldBounds().getExtent();
    EXPECT_GE(extent.x, 200.0f);
    EXPECT_LE(extent.x, 300.0f);
    EXPECT_GE(extent.z, 200.0f);
    EXPECT_LE(extent.z, 300.0f);
    EXPECT_LE(scene.countTriangles(), 4000u);
    // One ground material and the four-colour palette.
    EXPECT_EQ(scene.materials.size(), 5u);
}

TEST(BoxCity, GivenMaterialsReplaceTheDefaults) {
    Scene scene;
    Material brick;
    brick.name = "brick";
    brick.diffuse = {0.5f, 0.2f, 0.1f};
    scene.materials.push_back(brick);
    BoxCityParams params;
    params.buildingMaterial = 0;
    params.groundMaterial = 0;
    addBoxCity(scene, params, glm::mat4(1.0f));
    EXPECT_EQ(scene.materials.size(), 1u);
    for (uint32_t m : scene.meshes[0].triangleMaterials)
        EXPECT_EQ(m, 0u);
}

TEST(BoxCity, BadParametersThrow) {
    BoxCityParams params;
    params.buildingHeightM = {10.0f, 5.0f};
    EXPECT_TRUE(checkBoxCityParams(params).has_value());
    EXPECT_THROW(computeBoxCityLayout(params), std::invalid_argument);
}

bool isInsideXz(const Aabb& inner, const Aabb& outer) {
    return inner.lo.x >= outer.lo.x - kPositionSlackM &&
           inner.lo.z >= outer.lo.z - kPositionSlackM &&
           inner.hi.x <= outer.hi.x + kPositionSlackM && inner.hi.z <= outer.hi.z + kPositionSlackM;
}

bool isWithin(float v, const glm::vec2& range, float slack) {
    return v >= range.x - slack && v <= range.y + slack;
}

bool doOverlap(const Aabb& a, const Aabb& b) {
    return glm::all(glm::lessThan(a.lo, b.hi)) && glm::all(glm::lessThan(b.lo, a.hi));
}

void checkLayout(const BoxCityParams& p) {
    const BoxCityLayout layout = computeBoxCityLayout(p);
    ASSERT_FALSE(layout.boxes.empty());
    ASSERT_EQ(layout.boxes[0].kind, CityBoxKind::Ground);
    const size_t expectedBuildings =
        static_cast<size_t>(p.blocks.x) * p.blocks.y * p.lotsPerBlock.x * p.lotsPerBlock.y;
    EXPECT_EQ(layout.lots.size(), expectedBuildings);

    std::vector<int> attachmentCounts(layout.boxes.size(), 0);
    size_t buildingCount = 0;
    for (size_t i = 1; i < layout.boxes.size(); ++i) {
        const CityBox& b = layout.boxes[i];
        SCOPED_TRACE(::testing::Message() << "box " << i);
        EXPECT_TRUE(isInsideXz(b.box, layout.groundBounds));
        EXPECT_GE(b.box.lo.y, 0.0f);
        const Aabb& lot = layout.lots.at(b.lot);
        EXPECT_TRUE(isInsideXz(b.box, lot));
        const glm::vec3 extent = b.box.getExtent();
        EXPECT_TRUE(glm::all(glm::greaterThan(extent, glm::vec3(0.0f))));
        if (b.kind == CityBoxKind::Building) {
            ++buildingCount;
            EXPECT_EQ(b.box.lo.y, 0.0f);
            EXPECT_TRUE(isWithin(extent.y, p.buildingHeightM, kPositionSlackM));
            for (float inset : {b.box.lo.x - lot.lo.x, lot.hi.x - b.box.hi.x, b.box.lo.z - lot.lo.z,
                                lot.hi.z - b.box.hi.z}) {
                EXPECT_TRUE(isWithin(inset, p.buildingInsetM, kPositionSlackM)) << inset;
            }
            continue;
        }
        ASSERT_LT(b.building, i);
        const CityBox& building = layout.boxes[b.building];
        ASSERT_EQ(building.kind, CityBoxKind::Building);
        EXPECT_EQ(building.lot, b.lot);
        ++attachmentCounts[b.building];
        const glm::vec3 fraction = extent / building.box.getExtent();
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_TRUE(isWithin(fraction[axis], p.attachmentSize, kRatioSlack)) << fraction[axis];
        }
        EXPECT_TRUE(doOverlap(b.box, building.box)) << "attachment not attached";
        if (b.kind == CityBoxKind::RoofAttachment) {
            EXPECT_GT(b.box.hi.y, building.box.hi.y);
        } else {
            EXPECT_LE(b.box.hi.y, building.box.hi.y + kPositionSlackM);
        }
    }
    EXPECT_EQ(buildingCount, expectedBuildings);
    for (size_t i = 1; i < layout.boxes.size(); ++i) {
        if (layout.boxes[i].kind != CityBoxKind::Building) continue;
        EXPECT_GE(attachmentCounts[i], p.attachments.x);
        EXPECT_LE(attachmentCounts[i], p.attachments.y);
    }
}

TEST(BoxCity, EveryBoxWithinDeclaredRangesAndBounds) {
    constexpr uint64_t kSeeds[] = {0, 1, 2, 12345, 0xffffffffffffffffull};
    for (uint64_t seed : kSeeds) {
        SCOPED_TRACE(::testing::Message() << "seed " << seed);
        BoxCityParams defaults;
        defaults.seed = seed;
        checkLayout(defaults);

        BoxCityParams wide;
        wide.seed = seed;
        wide.blocks = {3, 2};
        wide.blockSizeM = {30.0f, 50.0f};
        wide.streetWidthM = 0.0f;
        wide.alleyWidthM = 0.0f;
        wide.lotsPerBlock = {3, 1};
        wide.buildingHeightM = {5.0f, 5.0f};
        wide.buildingInsetM = {0.0f, 4.0f};
        wide.attachments = {4, 8};
        wide.attachmentSize = {0.05f, 1.0f};
        checkLayout(wide);
    }
}

} // namespace
} // namespace ispm::test
