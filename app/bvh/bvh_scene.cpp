// Building the scene's two levels and keeping the top level in step with moving instances.
#include "bvh/bvh_scene.h"

#include <algorithm>
#include <cassert>
#include <utility>

namespace ispm {
namespace {

Aabb computeTriangleBounds(const Mesh& mesh, const glm::uvec3& tri) {
    Aabb box;
    for (int k = 0; k < 3; ++k)
        box.extend(mesh.positions[tri[k]]);
    return box;
}

// Appends a tree built over a mesh, shifting its indices to the shared arrays' numbering.
void appendBottomLevel(BvhScene& bvh, const BvhTree& tree, uint32_t firstTriangle) {
    const auto nodeBase = static_cast<uint32_t>(bvh.blasNodes.size());
    const auto orderBase = static_cast<uint32_t>(bvh.blasTriangleOrder.size());
    for (const gpu::GpuBvhNode& node : tree.nodes) {
        const Aabb box = getNodeBounds(node);
        if (isLeaf(node)) {
            bvh.blasNodes.push_back(
                makeLeafNode(box, getFirstPrimitive(node) + orderBase, getPrimitiveCount(node)));
        } else {
            bvh.blasNodes.push_back(makeInteriorNode(box, getLeftChild(node) + nodeBase,
                                                     getRightChild(node) + nodeBase));
        }
    }
    for (uint32_t local : tree.order)
        bvh.blasTriangleOrder.push_back(firstTriangle + local);
    bvh.meshBlasRoots.push_back(nodeBase);
}

void updateObjectFromWorld(BvhScene& bvh, const Scene& scene) {
    bvh.objectFromWorld.resize(scene.instances.size());
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        bvh.objectFromWorld[i] = glm::inverse(scene.instances[i].worldFromObject);
    }
}

} // namespace

Aabb computeInstanceBounds(const BvhScene& bvh, const Scene& scene, uint32_t instanceIndex) {
    const Instance& instance = scene.instances[instanceIndex];
    const Aabb local = getNodeBounds(bvh.blasNodes[bvh.meshBlasRoots[instance.meshIndex]]);
    return transformBounds(local, instance.worldFromObject);
}

BvhScene buildSceneBvh(const Scene& scene, const BvhBuildParams& meshParams) {
    BvhScene bvh;
    uint32_t firstTriangle = 0;
    std::vector<Aabb> bounds;
    for (const Mesh& mesh : scene.meshes) {
        bounds.clear();
        for (const glm::uvec3& tri : mesh.triangles) {
            bounds.push_back(computeTriangleBounds(mesh, tri));
        }
        const BvhTree tree = buildBvh(bounds, meshParams);
        bvh.blasDepth = std::max(bvh.blasDepth, tree.depth);
        bvh.meshFirstTriangles.push_back(firstTriangle);
        appendBottomLevel(bvh, tree, firstTriangle);
        firstTriangle += static_cast<uint32_t>(mesh.triangles.size());
    }
    rebuildTopLevel(bvh, scene);
    return bvh;
}

void rebuildTopLevel(BvhScene& bvh, const Scene& scene) {
    updateObjectFromWorld(bvh, scene);
    // Only instances with something to hit become primitives; `kept` maps back to instances.
    std::vector<Aabb> bounds;
    std::vector<uint32_t> kept;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        assert(scene.instances[i].meshIndex < bvh.meshBlasRoots.size());
        const Aabb box = computeInstanceBounds(bvh, scene, i);
        if (box.isEmpty()) continue;
        bounds.push_back(box);
        kept.push_back(i);
    }
    BvhTree tree = buildBvh(bounds, kTlasBuildParams);
    for (uint32_t& slot : tree.order)
        slot = kept[slot];
    bvh.tlasNodes = std::move(tree.nodes);
    bvh.tlasInstanceOrder = std::move(tree.order);
    bvh.tlasDepth = tree.depth;
}

void refitTopLevel(BvhScene& bvh, const Scene& scene) {
    assert(bvh.objectFromWorld.size() == scene.instances.size());
    updateObjectFromWorld(bvh, scene);
    // Children come after their parents, so a backward sweep sees children first.
    for (size_t n = bvh.tlasNodes.size(); n-- > 0;) {
        gpu::GpuBvhNode& node = bvh.tlasNodes[n];
        Aabb box;
        if (isLeaf(node)) {
            const uint32_t first = getFirstPrimitive(node);
            for (uint32_t k = 0; k < getPrimitiveCount(node); ++k) {
                box.extend(computeInstanceBounds(bvh, scene, bvh.tlasInstanceOrder[first + k]));
            }
        } else {
            box.extend(getNodeBounds(bvh.tlasNodes[getLeftChild(node)]));
            box.extend(getNodeBounds(bvh.tlasNodes[getRightChild(node)]));
        }
        setNodeBounds(node, box);
    }
}

} // namespace ispm
