// Photon buffer allocation and the counter read-back used by reports.
#include "render/photon_buffers.h"

#include "gl/gl.h"
#include "gl/state.h"

#include <algorithm>

namespace ispm {

void PhotonBuffers::reserve(uint32_t bounceCapacity, uint32_t resultCapacity) {
    mFrameResults = resultCapacity;
    if (bounceCapacity > mBounceCapacity || !mBounce.getId()) {
        mBounceCapacity = bounceCapacity;
        mBounce = gl::Buffer("bounce photons", size_t(bounceCapacity) * sizeof(gpu::BouncePhoton));
    }
    if (resultCapacity > mResultCapacity || !mResult.getId()) {
        mResultCapacity = resultCapacity;
        mResult = gl::Buffer("result photons", size_t(resultCapacity) * sizeof(gpu::ResultPhoton));
    }
}

void PhotonBuffers::startFrame(std::span<const glm::uvec4> grids, size_t lightCount) {
    // Never empty: a zero-size buffer cannot be bound (no grids: one that matches no photon).
    const glm::uvec4 none(0u);
    const std::span<const glm::uvec4> items = grids.empty() ? std::span(&none, 1) : grids;
    if (mGrids.getSize() != items.size_bytes())
        mGrids = gl::Buffer("emission grids", items.size_bytes());
    mGrids.upload(items);
    const size_t bytes = std::max<size_t>(lightCount, 1) * sizeof(gpu::LightPhotonCounters);
    if (mLightCounts.getSize() != bytes) mLightCounts = gl::Buffer("light photon counters", bytes);
    mLightCounts.clearToZero();
    mLightCount = lightCount;
}

void PhotonBuffers::bind() const {
    mBounce.bindBase(gl::BufferTarget::Storage, gpu::kBindingBouncePhotons);
    mResult.bindBase(gl::BufferTarget::Storage, gpu::kBindingResultPhotons);
    mCounters.bindBase(gl::BufferTarget::Storage, gpu::kBindingPhotonCounters);
    mSplatDraws.bindBase(gl::BufferTarget::Storage, gpu::kBindingSplatDraws);
    bindLightCounters();
}

void PhotonBuffers::bindLightCounters() const {
    mGrids.bindBase(gl::BufferTarget::Storage, gpu::kBindingEmissionGrids);
    mLightCounts.bindBase(gl::BufferTarget::Storage, gpu::kBindingLightCounts);
}

void PhotonBuffers::dispatchSlice(size_t countOffset, uint32_t slice, uint32_t slices,
                                  uint32_t photonsPerLane) const {
    // The count was written by a shader: the read must see it.
    gl::memoryBarrier(gl::Barrier::BufferUpdate);
    uint32_t count = 0;
    mCounters.download(countOffset, sizeof(count), &count);
    const glm::uvec2 range = gpu::computeSliceRange(count, slice, slices);
    const uint32_t groups = gpu::computeTraceGroups(range.y - range.x, photonsPerLane);
    if (groups > 0) gl::dispatchCompute(groups);
}

PhotonCounts PhotonBuffers::readCounts(const std::vector<uint32_t>& emitted) const {
    const gpu::PhotonCounters c = mCounters.read<gpu::PhotonCounters>(1)[0];
    PhotonCounts counts;
    for (uint32_t e : emitted)
        counts.emitted += e;
    if (mLightCount > 0) {
        const std::vector<gpu::LightPhotonCounters> lights =
            mLightCounts.read<gpu::LightPhotonCounters>(mLightCount);
        for (size_t i = 0; i < mLightCount; ++i) {
            const glm::uvec4 l = lights[i].counts;
            counts.perLight.push_back({i < emitted.size() ? emitted[i] : 0u, l.x, l.y, l.z});
            counts.inView += l.z;
        }
    }
    counts.bounced = c.bounce.x;
    counts.stored = std::min(c.result.x, c.result.y);
    counts.overflow = c.result.z;
    return counts;
}

} // namespace ispm
