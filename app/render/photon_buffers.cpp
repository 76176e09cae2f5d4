// Photon buffer allocation and the counter read-back used by reports.
#include "render/photon_buffers.h"

namespace ispm {

void PhotonBuffers::reserve(uint32_t bounceCapacity, uint32_t resultCapacity) {
    if (bounceCapacity > mBounceCapacity || !mBounce.getId()) {
        mBounceCapacity = bounceCapacity;
        mBounce = gl::Buffer("bounce photons", size_t(bounceCapacity) * sizeof(gpu::BouncePhoton));
    }
    if (resultCapacity > mResultCapacity || !mResult.getId()) {
        mResultCapacity = resultCapacity;
        mResult = gl::Buffer("result photons", size_t(resultCapacity) * sizeof(gpu::ResultPhoton));
    }
}

void PhotonBuffers::bind() const {
    mBounce.bindBase(gl::BufferTarget::Storage, gpu::kBindingBouncePhotons);
    mResult.bindBase(gl::BufferTarget::Storage, gpu::kBindingResultPhotons);
    mCounters.bindBase(gl::BufferTarget::Storage, gpu::kBindingPhotonCounters);
    mSplatDraws.bindBase(gl::BufferTarget::Storage, gpu::kBindingSplatDraws);
}

PhotonCounts PhotonBuffers::readCounts(uint32_t emitted) const {
    const gpu::PhotonCounters c = mCounters.read<gpu::PhotonCounters>(1)[0];
    PhotonCounts counts;
    counts.emitted = emitted;
    counts.bounced = c.bounce.x;
    counts.stored = std::min(c.result.x, c.result.y);
    counts.overflow = c.result.z;
    counts.inView = c.densityDispatch.w;
    return counts;
}

} // namespace ispm
