// The two-level BVH against brute force: random triangle soups of awkward sizes, transformed
// instances, the box city, moved instances and empty scenes; plus the tree's structural invariants
// (every primitive once, every box inside its parent's).
#include "bvh/bvh_traversal.h"
#include "core/strings.h"
#include "scene/box_city.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>
#include <random>

namespace ispm {
namespace {

// Both searches run the same triangle test on the same object-space ray, so t agrees far more
// tightly than this; the slack only allows for a future change in either path.
constexpr float kRelativeTSlack = 1e-5f;
constexpr int kRayCount = 10000;
constexpr size_t kLargeSoup = 10000;     // triangles; bigger soups get kLargeSoupRayCount rays
constexpr int kLargeSoupRayCount = 2500; // keeps the whole suite under 3 s
constexpr float kPi = 3.14159265f;

using NodeArray = std::vector<gpu::GpuBvhNode>;

bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) &&
           glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
}

glm::vec3 drawPoint(std::mt19937& rng, float lo, float hi) {
    std::uniform_real_distribution<float> u(lo, hi);
    const float x = u(rng);
    const float y = u(rng);
    return {x, y, u(rng)};
}

glm::vec3 drawDirection(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    const float x = n(rng);
    const float y = n(rng);
    const glm::vec3 d{x, y, n(rng)};
    return glm::length(d) > 0.0f ? glm::normalize(d) : glm::vec3(0.0f, 0.0f, 1.0f);
}

// Triangles of mixed sizes scattered through the unit cube: mostly small, a few long slivers.
Mesh makeSoup(std::mt19937& rng, size_t triangleCount, uint32_t material) {
    constexpr float kSmallEdge = 0.05f;
    constexpr float kLargeEdge = 0.6f;
    constexpr size_t kLargeEvery = 50;
    Mesh mesh;
    mesh.name = "soup";
    for (size_t t = 0; t < triangleCount; ++t) {
        const float edge = t % kLargeEvery == 0 ? kLargeEdge : kSmallEdge;
        const glm::vec3 c = drawPoint(rng, 0.0f, 1.0f);
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        for (int k = 0; k < 3; ++k)
            mesh.positions.push_back(c + drawPoint(rng, -edge, edge));
        mesh.triangles.emplace_back(base, base + 1, base + 2);
        mesh.triangleMaterials.push_back(material);
    }
    return mesh;
}

Scene makeSoupScene(std::mt19937& rng, size_t triangleCount) {
    Scene scene;
    scene.materials.push_back({});
    scene.meshes.push_back(makeSoup(rng, triangleCount, 0));
    scene.instances.push_back({0, glm::mat4(1.0f)});
    return scene;
}

// Walks the tree from root: boxes nest, children follow parents, leaves are small enough and
// cover order[begin, end) exactly once.
void expectValidTree(const NodeArray& nodes, uint32_t root, uint32_t begin, uint32_t end,
                     uint32_t maxLeafSize, const std::function<Aabb(uint32_t)>& getSlotBounds) {
    std::vector<int> slotVisits(end - begin, 0);
    std::vector<std::pair<uint32_t, uint32_t>> stack{{root, 0}}; // node, depth
    while (!stack.empty()) {
        const auto [index, depth] = stack.back();
        stack.pop_back();
        ASSERT_LT(depth, static_cast<uint32_t>(gpu::kBvhStackSize));
        const gpu::GpuBvhNode& node = nodes.at(index);
        const Aabb box = getNodeBounds(node);
        if (isLeaf(node)) {
            EXPECT_LE(getPrimitiveCount(node), maxLeafSize);
            for (uint32_t k = 0; k < getPrimitiveCount(node); ++k) {
                const uint32_t slot = getFirstPrimitive(node) + k;
                ASSERT_GE(slot, begin);
                ASSERT_LT(slot, end);
                ++slotVisits[slot - begin];
                EXPECT_TRUE(contains(box, getSlotBounds(slot))) << "leaf " << index;
            }
            continue;
        }
        for (uint32_t child : {getLeftChild(node), getRightChild(node)}) {
            ASSERT_GT(child, index);
            EXPECT_TRUE(contains(box, getNodeBounds(nodes.at(child)))) << "node " << child;
            stack.emplace_back(child, depth + 1);
        }
    }
    for (size_t s = 0; s < slotVisits.size(); ++s)
        ASSERT_EQ(slotVisits[s], 1) << "slot " << s;
}

void expectValidScene(const BvhScene& bvh, const Scene& scene) {
    const BvhBuildParams defaults;
    std::vector<uint32_t> sortedOrder = bvh.blasTriangleOrder;
    std::sort(sortedOrder.begin(), sortedOrder.end());
    size_t triangleCount = 0;
    for (const Mesh& mesh : scene.meshes)
        triangleCount += mesh.triangles.size();
    std::vector<uint32_t> expected(triangleCount);
    std::iota(expected.begin(), expected.end(), 0u);
    ASSERT_EQ(sortedOrder, expected) << "every triangle exactly once";
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const uint32_t first = bvh.meshFirstTriangles[m];
        const auto count = static_cast<uint32_t>(mesh.triangles.size());
        expectValidTree(bvh.blasNodes, bvh.meshBlasRoots[m], first, first + count,
                        defaults.maxLeafSize, [&](uint32_t slot) {
                            const uint32_t global = bvh.blasTriangleOrder[slot];
                            EXPECT_GE(global, first);
                            EXPECT_LT(global, first + count);
                            Aabb box;
                            for (int k = 0; k < 3; ++k) {
                                box.extend(mesh.positions[mesh.triangles[global - first][k]]);
                            }
                            return box;
                        });
    }
    expectValidTree(bvh.tlasNodes, 0, 0, static_cast<uint32_t>(bvh.tlasInstanceOrder.size()),
                    kTlasBuildParams.maxLeafSize, [&](uint32_t slot) {
                        return computeInstanceBounds(bvh, scene, bvh.tlasInstanceOrder[slot]);
                    });
}

std::string formatVec(const glm::vec3& v) {
    return strCat("(", v.x, ", ", v.y, ", ", v.z, ")");
}

// Counts the rays that hit; reports the first disagreement with brute force and stops there.
int expectMatchesBruteForce(const BvhScene& bvh, const Scene& scene, const std::vector<Ray>& rays) {
    int hitCount = 0;
    for (size_t r = 0; r < rays.size(); ++r) {
        const Ray& ray = rays[r];
        const std::optional<Hit> expected = intersectBruteForce(scene, ray);
        const std::optional<Hit> actual = intersect(bvh, scene, ray);
        bool ok = intersectAny(bvh, scene, ray) == expected.has_value() &&
                  actual.has_value() == expected.has_value();
        if (ok && expected) {
            ++hitCount;
            // Shadow rays stop short of the closest hit, or reach just past it.
            Ray shadow = ray;
            shadow.tMax = expected->t * (1.0f - kRelativeTSlack);
            const bool shortHits = intersectAny(bvh, scene, shadow);
            shadow.tMax = expected->t * (1.0f + kRelativeTSlack);
            const bool longHits = intersectAny(bvh, scene, shadow);
            ok = actual->instanceIndex == expected->instanceIndex &&
                 actual->triangleIndex == expected->triangleIndex &&
                 std::abs(actual->t - expected->t) <= kRelativeTSlack * expected->t && !shortHits &&
                 longHits;
        }
        if (!ok) {
            ADD_FAILURE() << "ray " << r << " from " << formatVec(ray.origin) << " along "
                          << formatVec(ray.direction) << ": expected "
                          << (expected ? strCat("instance ", expected->instanceIndex, " triangle ",
                                                expected->triangleIndex, " t ", expected->t)
                                       : std::string("a miss"))
                          << ", got "
                          << (actual ? strCat("instance ", actual->instanceIndex, " triangle ",
                                              actual->triangleIndex, " t ", actual->t)
                                     : std::string("a miss"));
            return hitCount;
        }
    }
    return hitCount;
}

std::vector<Ray> makeRays(std::mt19937& rng, int count, float lo, float hi) {
    std::vector<Ray> rays(static_cast<size_t>(count));
    for (Ray& ray : rays) {
        ray.origin = drawPoint(rng, lo, hi);
        ray.direction = drawDirection(rng);
    }
    return rays;
}

TEST(BvhSoup, MatchesBruteForceAtAwkwardSizes) {
    for (size_t triangleCount : {size_t{1}, size_t{7}, size_t{1000}, size_t{12345}}) {
        SCOPED_TRACE(triangleCount);
        std::mt19937 rng(static_cast<uint32_t>(triangleCount));
        const Scene scene = makeSoupScene(rng, triangleCount);
        const BvhScene bvh = buildSceneBvh(scene);
        expectValidScene(bvh, scene);
        // Origins partly inside the soup, partly around it.
        // Brute force on the largest soup dominates the suite's time: fewer rays there.
        const int rayCount = triangleCount > kLargeSoup ? kLargeSoupRayCount : kRayCount;
        const int hits = expectMatchesBruteForce(bvh, scene, makeRays(rng, rayCount, -0.5f, 1.5f));
        if (triangleCount >= 1000) {
            EXPECT_GT(hits, rayCount / 5);
        }
    }
}

TEST(BvhInstances, TransformedInstancesMatchBruteForce) {
    constexpr int kInstanceCount = 40;
    std::mt19937 rng(7);
    Scene scene;
    scene.materials.push_back({});
    scene.meshes.push_back(makeSoup(rng, 150, 0));
    scene.meshes.push_back(makeSoup(rng, 7, 0));
    scene.meshes.push_back({}); // no triangles: must be skipped everywhere
    std::uniform_real_distribution<float> scale(0.3f, 3.0f);
    std::uniform_real_distribution<float> angle(0.0f, 2.0f * kPi);
    for (int i = 0; i < kInstanceCount; ++i) {
        glm::mat4 m = glm::translate(glm::mat4(1.0f), drawPoint(rng, -4.0f, 4.0f));
        m = glm::rotate(m, angle(rng), drawDirection(rng));
        const float sx = scale(rng);
        const float sy = scale(rng);
        m = glm::scale(m, glm::vec3(sx, sy, i % 5 == 0 ? -scale(rng) : scale(rng)));
        scene.instances.push_back({static_cast<uint32_t>(i % 3), m});
    }
    const BvhScene bvh = buildSceneBvh(scene);
    expectValidScene(bvh, scene);
    const std::vector<Ray> rays = makeRays(rng, kRayCount, -6.0f, 6.0f);
    EXPECT_GT(expectMatchesBruteForce(bvh, scene, rays), kRayCount / 20);
    // t is a world distance: the hit point lies on the world-space triangle.
    constexpr float kPlaneSlackM = 1e-4f;
    for (const Ray& ray : rays) {
        const std::optional<Hit> hit = intersect(bvh, scene, ray);
        if (!hit) continue;
        const Instance& inst = scene.instances[hit->instanceIndex];
        const Mesh& mesh = scene.meshes[inst.meshIndex];
        const glm::uvec3 tri =
            mesh.triangles[hit->triangleIndex - bvh.meshFirstTriangles[inst.meshIndex]];
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = glm::vec3(inst.worldFromObject * glm::vec4(mesh.positions[tri[k]], 1.0f));
        }
        const glm::vec2 b = hit->barycentrics;
        const glm::vec3 expected = (1.0f - b.x - b.y) * p[0] + b.x * p[1] + b.y * p[2];
        ASSERT_LT(glm::length(ray.origin + hit->t * ray.direction - expected), kPlaneSlackM);
    }
}

TEST(BvhInstances, ThousandsOfInstances) {
    constexpr int kInstanceCount = 3000;
    constexpr int kFewRays = 300; // brute force inverts every instance's matrix per ray
    std::mt19937 rng(11);
    Scene scene;
    scene.materials.push_back({});
    scene.meshes.push_back(makeSoup(rng, 2, 0));
    for (int i = 0; i < kInstanceCount; ++i) {
        scene.instances.push_back(
            {0, glm::translate(glm::mat4(1.0f), drawPoint(rng, -20.0f, 20.0f))});
    }
    BvhScene bvh = buildSceneBvh(scene);
    expectValidScene(bvh, scene);
    EXPECT_GT(expectMatchesBruteForce(bvh, scene, makeRays(rng, kFewRays, -20.0f, 20.0f)), 0);
    const auto start = std::chrono::steady_clock::now();
    rebuildTopLevel(bvh, scene);
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    std::printf("%d instances: top level rebuilt in %.3f ms\n", kInstanceCount, elapsed.count());
}

TEST(BvhBoxCity, MatchesBruteForce) {
    Scene scene;
    addBoxCity(scene, BoxCityParams{}, glm::mat4(1.0f));
    const auto start = std::chrono::steady_clock::now();
    constexpr int kBuildRepeats = 20;
    for (int i = 0; i + 1 < kBuildRepeats; ++i)
        (void)buildSceneBvh(scene);
    const BvhScene bvh = buildSceneBvh(scene);
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    std::printf("box city: %zu triangles, %zu BLAS nodes, depth %u, build %.3f ms\n",
                scene.countTriangles(), bvh.blasNodes.size(), bvh.blasDepth,
                elapsed.count() / kBuildRepeats);
    expectValidScene(bvh, scene);
    // Rays from a box around the city (which is ~250 m across, up to ~50 m tall).
    constexpr float kCityHalfM = 130.0f;
    std::mt19937 rng(3);
    std::vector<Ray> rays = makeRays(rng, kRayCount, -kCityHalfM, kCityHalfM);
    for (Ray& ray : rays)
        ray.origin.y = std::abs(ray.origin.y) * 0.5f;
    EXPECT_GT(expectMatchesBruteForce(bvh, scene, rays), kRayCount / 3);
}

TEST(BvhTopLevel, RebuildAndRefitFollowAMovedInstance) {
    Scene scene;
    scene.materials.push_back({});
    Mesh quad; // unit square in the z = 0 plane, two triangles
    quad.positions = {
        {-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}};
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.triangleMaterials = {0, 0};
    scene.meshes.push_back(quad);
    scene.instances.push_back({0, glm::mat4(1.0f)});
    scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 0.0f, 0.0f))});
    BvhScene bvh = buildSceneBvh(scene);

    const glm::vec3 moved{-3.0f, 2.0f, -4.0f};
    Ray atOld{{0.1f, 0.1f, 10.0f}, {0.0f, 0.0f, -1.0f}};
    Ray atNew{moved + glm::vec3(0.1f, 0.1f, 10.0f), {0.0f, 0.0f, -1.0f}};
    std::optional<Hit> hit = intersect(bvh, scene, atOld);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instanceIndex, 0u);
    EXPECT_FLOAT_EQ(hit->t, 10.0f);
    EXPECT_FALSE(intersect(bvh, scene, atNew));

    scene.instances[0].worldFromObject = glm::translate(glm::mat4(1.0f), moved);
    for (bool refit : {false, true}) {
        SCOPED_TRACE(refit ? "refit" : "rebuild");
        BvhScene updated = bvh;
        if (refit) {
            refitTopLevel(updated, scene);
        } else {
            rebuildTopLevel(updated, scene);
        }
        expectValidScene(updated, scene);
        EXPECT_FALSE(intersect(updated, scene, atOld));
        hit = intersect(updated, scene, atNew);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->instanceIndex, 0u);
        EXPECT_FLOAT_EQ(hit->t, 10.0f);
        EXPECT_TRUE(intersectAny(updated, scene, atNew));
    }
}

TEST(BvhEdgeCases, EmptySceneAndEmptyMesh) {
    Scene scene;
    BvhScene bvh = buildSceneBvh(scene);
    ASSERT_EQ(bvh.tlasNodes.size(), 1u);
    const Ray ray{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}};
    EXPECT_FALSE(intersect(bvh, scene, ray));
    EXPECT_FALSE(intersectAny(bvh, scene, ray));
    EXPECT_FALSE(intersectBruteForce(scene, ray));

    scene.meshes.push_back({});
    scene.instances.push_back({0, glm::mat4(1.0f)});
    bvh = buildSceneBvh(scene);
    expectValidScene(bvh, scene);
    EXPECT_TRUE(bvh.tlasInstanceOrder.empty());
    EXPECT_FALSE(intersect(bvh, scene, ray));
    EXPECT_FALSE(intersectAny(bvh, scene, ray));
}

TEST(BvhEdgeCases, OneTriangle) {
    Scene scene;
    scene.materials.push_back({});
    Mesh mesh;
    mesh.positions = {{0.0f, 0.0f, -2.0f}, {3.0f, 0.0f, -2.0f}, {0.0f, 3.0f, -2.0f}};
    mesh.triangles = {{0, 1, 2}};
    mesh.triangleMaterials = {0};
    scene.meshes.push_back(mesh);
    // A scale of 2 doubles every distance: t must come out in world units.
    scene.instances.push_back({0, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))});
    const BvhScene bvh = buildSceneBvh(scene);
    expectValidScene(bvh, scene);

    Ray ray{{2.0f, 2.0f, 0.0f}, {0.0f, 0.0f, -1.0f}};
    const std::optional<Hit> hit = intersect(bvh, scene, ray);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->triangleIndex, 0u);
    EXPECT_FLOAT_EQ(hit->t, 4.0f);
    EXPECT_NEAR(hit->barycentrics.x, 1.0f / 3.0f, 1e-6f);
    EXPECT_NEAR(hit->barycentrics.y, 1.0f / 3.0f, 1e-6f);
    // From behind (no culling), short of it, and in its plane.
    EXPECT_TRUE(intersect(bvh, scene, {{2.0f, 2.0f, -8.0f}, {0.0f, 0.0f, 1.0f}}));
    ray.tMax = 3.9f;
    EXPECT_FALSE(intersect(bvh, scene, ray));
    EXPECT_FALSE(intersectAny(bvh, scene, ray));
    EXPECT_FALSE(intersect(bvh, scene, {{-1.0f, 1.0f, -4.0f}, {1.0f, 0.0f, 0.0f}}));
}

} // namespace
} // namespace ispm
