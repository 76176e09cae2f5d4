// FlickerMeter: running sums per pixel, and the distance from each pixel's point to the boxes
// of the moving instances in every frame.
#include "cli/bench_flicker.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ispm {
namespace {

float computeDistanceToBox(const glm::vec3& p, const Aabb& box) {
    const glm::vec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), glm::vec3(0.0f));
    return glm::length(outside);
}

double computeMeanLight(const glm::vec3& rgb) {
    return (double(rgb.x) + double(rgb.y) + double(rgb.z)) / 3.0;
}

} // namespace

void FlickerMeter::addFrame(const Image& indirect, const std::vector<glm::vec4>& positions,
                            const Scene& scene) {
    const size_t n = indirect.pixels.size();
    if (mFrames == 0) {
        mSum.assign(n, 0.0);
        mSumSquares.assign(n, 0.0);
        mNearestMovingM.assign(n, std::numeric_limits<float>::max());
        mSurface.assign(n, false);
        for (size_t i = 0; i < n && i < positions.size(); ++i)
            mSurface[i] = positions[i].w > 0.5f;
    }
    std::vector<Aabb> moving;
    for (const InstanceAnimation& a : scene.instanceAnimations) {
        const Instance& instance = scene.instances[a.instanceIndex];
        moving.push_back(transformBounds(scene.meshes[instance.meshIndex].computeBounds(),
                                         instance.worldFromObject));
    }
    for (size_t i = 0; i < n; ++i) {
        const double light = computeMeanLight(indirect.pixels[i]);
        mSum[i] += light;
        mSumSquares[i] += light * light;
        if (i >= positions.size() || positions[i].w <= 0.5f) continue;
        for (const Aabb& box : moving) {
            mNearestMovingM[i] =
                std::min(mNearestMovingM[i], computeDistanceToBox(glm::vec3(positions[i]), box));
        }
    }
    ++mFrames;
}

FlickerResult FlickerMeter::getResult() const {
    FlickerResult r;
    r.frames = mFrames;
    r.awayM = mAwayM;
    if (mFrames < 2) return r;
    double stdAll = 0.0;
    double meanAll = 0.0;
    double stdAway = 0.0;
    double meanAway = 0.0;
    for (size_t i = 0; i < mSum.size(); ++i) {
        if (!mSurface[i]) continue;
        const double mean = mSum[i] / mFrames;
        const double variance = std::max(mSumSquares[i] / mFrames - mean * mean, 0.0);
        const double deviation = std::sqrt(variance * mFrames / (mFrames - 1)); // sample std
        ++r.pixels;
        stdAll += deviation;
        meanAll += mean;
        if (double(mNearestMovingM[i]) > mAwayM) {
            ++r.awayPixels;
            stdAway += deviation;
            meanAway += mean;
        }
    }
    r.all = meanAll > 0.0 ? stdAll / meanAll : 0.0;
    r.away = meanAway > 0.0 ? stdAway / meanAway : 0.0;
    return r;
}

} // namespace ispm
