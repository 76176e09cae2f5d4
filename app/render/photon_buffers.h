// The photon buffers the emit, trace and splat passes share: bounce buffer (transform feedback
// target), result buffer, and the counters/indirect-argument block (shared/photon_data.h).
#pragma once

#include "gl/objects.h"

#include <shared/photon_data.h>

#include <cstdint>
#include <span>
#include <vector>

namespace ispm {

// The counts of one light (or, in PhotonCounts, of all together).
struct LightCounts {
    uint32_t emitted = 0; // grid photons drawn (before the first bounce)
    uint32_t bounced = 0; // survivors of the first bounce
    uint32_t stored = 0;  // result photons kept
    uint32_t inView = 0;  // stored photons whose splat reaches the view
};

struct PhotonCounts {
    uint32_t emitted = 0;              // grid photons drawn (before the first bounce)
    uint32_t bounced = 0;              // survivors of the first bounce, in the bounce buffer
    uint32_t stored = 0;               // result photons kept
    uint32_t overflow = 0;             // result photons dropped for want of capacity
    uint32_t inView = 0;               // stored photons whose splat reaches the view
    std::vector<LightCounts> perLight; // by light index; emitted and inView are their sums
};

class PhotonBuffers {
  public:
    // Grows (never shrinks) to hold `bounceCapacity` bounce photons and `resultCapacity` results,
    // the most this frame can store (getFrameResults).
    void reserve(uint32_t bounceCapacity, uint32_t resultCapacity);
    // The frame's emission grids ({first photon, view} in photon order, for the GPU to find a
    // photon's light) and `lightCount` per-light counters set to zero.
    void startFrame(std::span<const glm::uvec4> grids, size_t lightCount);
    // Storage bindings kBinding{Bounce,Result}Photons, kBindingPhotonCounters, kBindingSplatDraws,
    // kBindingEmissionGrids, kBindingLightCounts.
    void bind() const;
    // Only the grids and the per-light counters (the emit pass, whose bounce buffer is bound
    // for transform feedback).
    void bindLightCounters() const;

    const gl::Buffer& getBounce() const { return mBounce; }
    const gl::Buffer& getResult() const { return mResult; }
    const gl::Buffer& getCounters() const { return mCounters; }
    const gl::Buffer& getSplatDraws() const { return mSplatDraws; }
    uint32_t getBounceCapacity() const { return mBounceCapacity; }
    uint32_t getResultCapacity() const { return mResultCapacity; }
    // The result photons this frame can store at most (its photons x bounces): what the
    // per-photon tables of later passes hold, however large an earlier frame left the buffers.
    uint32_t getFrameResults() const { return mFrameResults; }
    // Dispatches the photon pass bound now (groups of kTraceGroupSize, `photonsPerLane` photons
    // a lane: computeTraceGroups) over slice `slice` of `slices` of the photons counted at
    // `countOffset` in the counters (computeSliceRange): the count is read back first, a wait the
    // viewer's sliced frames make anyway. Nothing to do for an empty slice.
    void dispatchSlice(size_t countOffset, uint32_t slice, uint32_t slices,
                       uint32_t photonsPerLane = 1) const;
    // Reads the counters back: for reports and tests, never inside a frame. `emitted` per light.
    PhotonCounts readCounts(const std::vector<uint32_t>& emitted) const;
    size_t getGpuBytes() const {
        return mBounce.getSize() + mResult.getSize() + mCounters.getSize() + mSplatDraws.getSize() +
               mGrids.getSize() + mLightCounts.getSize();
    }

  private:
    gl::Buffer mBounce;
    gl::Buffer mResult;
    gl::Buffer mCounters{"photon counters", sizeof(gpu::PhotonCounters)};
    gl::Buffer mSplatDraws{"splat draw commands",
                           gpu::kMaxSplatDraws* gpu::kSplatDrawUvec4s * sizeof(glm::uvec4)};
    // One entry each until the first frame sets them: bindable from the start (a zero-size buffer
    // is not), and matching no light.
    gl::Buffer mGrids{"emission grids", sizeof(glm::uvec4)};
    gl::Buffer mLightCounts{"light photon counters", sizeof(gpu::LightPhotonCounters)};
    size_t mLightCount = 0;
    uint32_t mBounceCapacity = 0;
    uint32_t mResultCapacity = 0;
    uint32_t mFrameResults = 0;
};

} // namespace ispm
