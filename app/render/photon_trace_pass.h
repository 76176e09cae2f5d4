// PhotonTracePass (compute): the bounce photons traced through the BVH for up to `bounces` more
// hits, appending result photons. Dispatch size, counters and the splat pass's draw arguments are
// all derived on the GPU from the emitted count.
#pragma once

#include "render/pass.h"
#include "render/photon_buffers.h"

namespace ispm {

class PhotonTracePass final : public Pass {
  public:
    explicit PhotonTracePass(PhotonBuffers& buffers);
    const char* getName() const override { return "trace"; }
    void execute(const FrameInputs& inputs) override;
    // Slice `slice` of `slices` of the bounce photons (a frame drawn in slices): the first turns
    // the bounce count into the dispatch, the last the results into the splat's draws.
    void executeSlice(const FrameInputs& inputs, uint32_t slice, uint32_t slices);
    void reloadPrograms(ShaderReloadReport& report) override {
        mPrepare.reloadIfChanged(report);
        mTrace.reloadIfChanged(report);
    }

  private:
    PhotonBuffers& mBuffers;
    ReloadableProgram mPrepare;
    ProgramVariants mTrace;    // by the scene's ray tests (GpuScene::getRayDefines)
    gl::Buffer mPrepareParams; // gpu::PrepareParams
    gl::Buffer mTraceParams;   // gpu::TraceParams
    uint32_t mPhotonsPerLane;  // photon_trace.comp: 1, or kTracePhotonsPerLaneSoftware on llvmpipe
};

} // namespace ispm
