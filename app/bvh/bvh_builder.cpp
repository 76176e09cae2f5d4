// Binned SAH construction (Wald 2007): centroids are binned along the longest axis of their
// bounds, the cheapest of the bin boundaries splits the node, small nodes become leaves.
#include "bvh/bvh_builder.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <numeric>

namespace ispm {
namespace {

// Past this depth nodes split at the centroid median, which halves them: the tree then ends
// within log2(n) further levels and stays inside the GPU traversal stack (2^20 leaves of room).
constexpr uint32_t kMedianSplitDepth = static_cast<uint32_t>(gpu::kBvhStackSize) - 20;
// Guards the division by a flat node's area; such nodes are leaves whenever they may be.
constexpr float kMinArea = std::numeric_limits<float>::min();

struct BuildTask {
    uint32_t node;
    uint32_t begin; // range in order
    uint32_t end;
    uint32_t depth;
};

struct Bin {
    Aabb bounds;
    uint32_t count = 0;
};

int getLongestAxis(const glm::vec3& extent) {
    if (extent.x >= extent.y && extent.x >= extent.z) return 0;
    return extent.y >= extent.z ? 1 : 2;
}

class Builder {
  public:
    Builder(std::span<const Aabb> bounds, const BvhBuildParams& params)
        : mBounds(bounds), mParams(params), mCentroids(bounds.size()) {
        assert(params.maxLeafSize >= 1 && params.binCount >= 2);
        for (size_t i = 0; i < bounds.size(); ++i)
            mCentroids[i] = bounds[i].getCenter();
    }

    BvhTree build() {
        BvhTree tree;
        tree.order.resize(mBounds.size());
        std::iota(tree.order.begin(), tree.order.end(), 0u);
        tree.nodes.push_back(makeLeafNode(Aabb{}, 0, 0));
        std::vector<BuildTask> tasks{{0, 0, static_cast<uint32_t>(mBounds.size()), 0}};
        while (!tasks.empty()) {
            const BuildTask task = tasks.back();
            tasks.pop_back();
            tree.depth = std::max(tree.depth, task.depth);
            const uint32_t mid = splitOrMakeLeaf(task, tree);
            if (mid == task.begin) continue; // leaf
            const auto left = static_cast<uint32_t>(tree.nodes.size());
            tree.nodes.push_back({});
            tree.nodes.push_back({});
            setInterior(tree, task.node, left);
            tasks.push_back({left, task.begin, mid, task.depth + 1});
            tasks.push_back({left + 1, mid, task.end, task.depth + 1});
        }
        assert(tree.depth < static_cast<uint32_t>(gpu::kBvhStackSize));
        return tree;
    }

  private:
    static void setInterior(BvhTree& tree, uint32_t node, uint32_t left) {
        tree.nodes[node] = makeInteriorNode(getNodeBounds(tree.nodes[node]), left, left + 1);
    }

    // Writes the node's box; returns the split point in order, or task.begin after making a leaf.
    uint32_t splitOrMakeLeaf(const BuildTask& task, BvhTree& tree) {
        Aabb box;
        Aabb centroidBox;
        for (uint32_t i = task.begin; i < task.end; ++i) {
            box.extend(mBounds[tree.order[i]]);
            centroidBox.extend(mCentroids[tree.order[i]]);
        }
        const uint32_t count = task.end - task.begin;
        const bool mayBeLeaf = count <= mParams.maxLeafSize;
        const auto makeLeaf = [&] {
            tree.nodes[task.node] = makeLeafNode(box, task.begin, count);
            return task.begin;
        };
        tree.nodes[task.node] = makeInteriorNode(box, 0, 0);
        const int axis = getLongestAxis(centroidBox.getExtent());
        auto* first = tree.order.data() + task.begin;
        auto* last = tree.order.data() + task.end;
        const float extent = centroidBox.getExtent()[axis];
        if (count <= 1 || (mayBeLeaf && (extent <= 0.0f || task.depth >= kMedianSplitDepth))) {
            return makeLeaf();
        }
        if (extent <= 0.0f || task.depth >= kMedianSplitDepth) {
            // Coincident centroids cannot be told apart: any halving is as good as another.
            const uint32_t mid = task.begin + count / 2;
            std::nth_element(first, tree.order.data() + mid, last, [&](uint32_t a, uint32_t b) {
                return mCentroids[a][axis] < mCentroids[b][axis];
            });
            return mid;
        }
        const uint32_t binCount = mParams.binCount;
        const float lo = centroidBox.lo[axis];
        const float scale = static_cast<float>(binCount) / extent;
        const auto getBin = [&](uint32_t prim) {
            const auto bin = static_cast<uint32_t>((mCentroids[prim][axis] - lo) * scale);
            return std::min(bin, binCount - 1);
        };
        std::vector<Bin> bins(binCount);
        for (uint32_t i = task.begin; i < task.end; ++i) {
            Bin& bin = bins[getBin(tree.order[i])];
            bin.bounds.extend(mBounds[tree.order[i]]);
            ++bin.count;
        }
        // rightCost[b]: area x count of bins b.. binCount-1, swept from the right.
        std::vector<float> rightCost(binCount, 0.0f);
        Aabb rightBox;
        uint32_t rightCount = 0;
        for (uint32_t b = binCount - 1; b > 0; --b) {
            rightBox.extend(bins[b].bounds);
            rightCount += bins[b].count;
            rightCost[b] = computeSurfaceArea(rightBox) * static_cast<float>(rightCount);
        }
        Aabb leftBox;
        uint32_t leftCount = 0;
        float bestCost = std::numeric_limits<float>::max();
        uint32_t bestSplit = 1; // first bin of the right side
        for (uint32_t b = 1; b < binCount; ++b) {
            leftBox.extend(bins[b - 1].bounds);
            leftCount += bins[b - 1].count;
            const float cost =
                computeSurfaceArea(leftBox) * static_cast<float>(leftCount) + rightCost[b];
            if (leftCount > 0 && leftCount < count && cost < bestCost) {
                bestCost = cost;
                bestSplit = b;
            }
        }
        // A node small enough for a leaf stays one unless the SAH says splitting is cheaper; a
        // bigger node is split even when the SAH would keep it whole.
        const float area = computeSurfaceArea(box);
        const float splitCost =
            mParams.traversalCost + mParams.intersectionCost * bestCost / std::max(area, kMinArea);
        const float leafCost = mParams.intersectionCost * static_cast<float>(count);
        if (mayBeLeaf && (area <= 0.0f || splitCost >= leafCost)) return makeLeaf();
        auto* midPtr =
            std::partition(first, last, [&](uint32_t prim) { return getBin(prim) < bestSplit; });
        const auto mid = static_cast<uint32_t>(midPtr - tree.order.data());
        assert(mid > task.begin && mid < task.end);
        return mid;
    }

    std::span<const Aabb> mBounds;
    BvhBuildParams mParams;
    std::vector<glm::vec3> mCentroids;
};

} // namespace

float computeSurfaceArea(const Aabb& box) {
    if (box.isEmpty()) return 0.0f;
    const glm::vec3 e = box.getExtent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

BvhTree buildBvh(std::span<const Aabb> primitiveBounds, const BvhBuildParams& params) {
    return Builder(primitiveBounds, params).build();
}

} // namespace ispm
