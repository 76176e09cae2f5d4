// PhotonEmitPass: for each light view a regular vertex grid goes through a geometry shader that
// reads the light's G-buffer, makes the first bounce and writes survivors into the bounce buffer
// by transform feedback. The number written goes from a query into the counters buffer on the GPU.
// Then each group of emitting triangles (docs/design.md "Emitters") sends its photons from points
// on them through the BVH to their first hit (photon/emitter_emit.comp), and the environment its
// own from a disc around the scene (photon/environment_emit.comp), bounced there as the geometry
// shader bounces a light view's and appended after them.
#pragma once

#include "render/gbuffer.h"
#include "render/param_blocks.h"
#include "render/pass.h"
#include "render/photon_budget.h"
#include "render/photon_buffers.h"

#include <shared/emitter_data.h>
#include <shared/environment_data.h>
#include <shared/photon_data.h>

namespace ispm {

class PhotonEmitPass final : public Pass {
  public:
    // `importanceCdf`: the light views' sampling tables (ImportancePass), read by the geometry
    // stage.
    PhotonEmitPass(const GBuffer& lightGBuffer, const gl::Buffer& importanceCdf,
                   PhotonBuffers& buffers);
    const char* getName() const override { return "emit"; }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override {
        mProgram.reloadIfChanged(report);
        mEmitterProgram.reloadIfChanged(report);
        mEnvironmentProgram.reloadIfChanged(report);
    }
    // The grids of the last frame (emitted = their photon total).
    const std::vector<EmissionGrid>& getGrids() const { return mGrids; }
    // Photons emitted per light (light index order), then per emitter group, in the last frame.
    std::vector<uint32_t> getEmittedPerLight() const;

  private:
    // The emitting triangles' and the environment's photons, traced to their first hit.
    void emitFromSurfacesAndSky(const FrameInputs& inputs);

    const GBuffer& mLightGBuffer;
    const gl::Buffer& mImportanceCdf;
    PhotonBuffers& mBuffers;
    ReloadableProgram mProgram;
    ReloadableProgram mEmitterProgram; // photon/emitter_emit.comp
    ParamBlocks<gpu::EmitterEmitParams> mEmitterParams{"emitter photon parameters"};
    ReloadableProgram mEnvironmentProgram; // photon/environment_emit.comp
    ParamBlocks<gpu::EnvironmentEmitParams> mEnvironmentParams{"environment photon parameters"};
    ParamBlocks<gpu::EmitParams> mParams{"photon emit parameters"}; // one per grid
    gl::VertexArray mVertexArray;
    gl::Framebuffer mFramebuffer;
    gl::TransformFeedback mFeedback;
    gl::Query mWritten;
    std::vector<EmissionGrid> mGrids;
    std::vector<uint32_t> mGridLights; // light of each grid
    size_t mLightCount = 0;
};

} // namespace ispm
