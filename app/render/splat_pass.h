// SplatPass: every result photon is drawn as an instanced flat square in its surface plane (or,
// splat_shape box, a box squashed along its normal); the fragment stage adds BRDF x power x
// kernel to the indirect-light buffer (additive RGBA32F). splat_mode gather bins the photons
// into screen tiles instead, and each pixel sums its tile's photons (shared/gather_data.h).
// The draw count comes from the GPU (glDrawArraysIndirect), split into `splat_passes` calls
// (more when the viewer draws a frame in slices).
// The buffer may be smaller than the image (`splat_resolution`): each of its pixels then shades
// one viewer G-buffer pixel of the block it covers, and UpsamplePass brings it back. In
// radius_mode density the caustic photons (shared/photon_data.h, kSplatCausticPhotons) are drawn
// apart, into a buffer of the image's size that the filter leaves alone and UpsamplePass adds.
#pragma once

#include "render/gbuffer.h"
#include "render/param_blocks.h"
#include "render/pass.h"
#include "render/photon_buffers.h"
#include "render/photon_density_pass.h"
#include "render/splat_radii.h"
#include "scene/scene.h"

#include <optional>
#include <shared/photon_data.h>

namespace ispm {

// One line for stderr when the settings make splat discs so wide that much of a photon's power
// lands where no surface is and the indirect light fades (radius_mode travel or path_density
// with a large radius_scale or radius_max): the largest radius is over a fifth of the scene's
// diagonal. On the Cornell box, radius_scale 5 (0.21 of the diagonal) keeps 80% of the light,
// 10 keeps 62%, 30 keeps 19%. Density radii are bounded by their neighbours and their travel.
// "" when none.
std::string describeOversizedSplats(double surfaceAreaM2, float diagonalM,
                                    const FrameSettings& settings);

class SplatPass final : public Pass {
  public:
    // The density pass's clip distances and list of caustic photons are read when radius_mode
    // is density.
    SplatPass(const GBuffer& viewer, const PhotonBuffers& buffers,
              const PhotonDensityPass& density);
    const char* getName() const override { return "splat"; }
    // The buffer follows the image size and `splat_resolution` at each execute.
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override {
        mPrograms.reloadIfChanged(report);
        mBinCount.reloadIfChanged(report);
        mBinFill.reloadIfChanged(report);
        mScan.reloadIfChanged(report);
        mGather.reloadIfChanged(report);
    }
    // The tiled gather's buffers (they grow to the largest frame's need).
    size_t getGpuBytes() const { return mTiles.getSize() + mList.getSize(); }
    const gl::Texture& getOutput() const { return mIndirect; }
    // The caustic photons' light at the image's resolution (black unless separatesCaustics).
    const gl::Texture& getCaustics() const { return mCaustics; }
    // Whether the caustic photons are splatted apart: in radius_mode density.
    static bool separatesCaustics(const FrameSettings& settings);
    // Where the raster splat draws a buffer of `size` pixels in its target: a buffer under two
    // rasteriser tiles across (64 px) is centred on a tile border, so that its pixels spread over
    // two tiles instead of one. llvmpipe shades each tile on one thread: the splat of a 64 x 64
    // buffer (a 128 x 128 image's at 1/2) took as long on two threads as on one.
    static glm::ivec2 computeTargetOffset(glm::ivec2 size);
    // The raster splat's draws [firstDraw, firstDraw + drawCount) of inputs.splatDraws, each a
    // share of the photons in order (so slices add up to execute()'s image exactly); the first
    // clears the buffer. Not for splat_mode gather.
    void executeDraws(const FrameInputs& inputs, uint32_t firstDraw, uint32_t drawCount);
    // No photons this frame: the buffer, sized as execute would, holds no light.
    void clear(const FrameInputs& inputs);

  private:
    void resizeBuffers(const FrameInputs& inputs);
    void executeGather(const FrameInputs& inputs);
    // Binds what every raster draw reads and sets the blend and cull state.
    void bindRaster(const FrameInputs& inputs);
    // Draw p of inputs.splatDraws with parameter block p.
    void drawSplats(uint32_t p);
    // radius_mode density: the raster's draws take the density pass's disc list (getDiscOffset)
    // instead of every stored photon (the density pass wrote their commands).
    static bool drawsDiscList(const FrameInputs& inputs);
    // The caustic photons' draw, into the caustic buffer (its block follows the draws').
    void drawCaustics(const FrameInputs& inputs);
    // Writes the parameter blocks of every draw, then the caustic draw's.
    void uploadParams(const FrameInputs& inputs);

    const GBuffer& mViewer;
    const PhotonBuffers& mBuffers;
    const PhotonDensityPass& mDensity;
    // The raster program's variants: with the density radii's clip lines (SPLAT_CLIP_LINES 1)
    // or for the radius modes that clip nothing, which then pay for neither the lines'
    // varyings nor their per-pixel loop; and the scene's reflection model
    // (GpuScene::getSurfaceDefines).
    ProgramVariants mPrograms;
    gl::VertexArray mCubeVertexArray; // splat_shape box
    gl::VertexArray mDiscVertexArray; // splat_shape disc
    gl::Buffer mCubeIndices;
    gl::Buffer mDiscIndices;
    ParamBlocks<gpu::SplatParams> mParams{"splat parameters"}; // one per draw
    gl::Texture mIndirect;
    gl::Framebuffer mFramebuffer;
    // The raster splat's target when computeTargetOffset is not zero: the buffer at that offset,
    // copied into mIndirect after the last draw.
    gl::Texture mTarget;
    gl::Framebuffer mTargetFramebuffer;
    gl::Texture mCaustics;
    gl::Framebuffer mCausticFramebuffer;
    // splat_mode gather: binning (count, then fill), the tiles' list offsets, the gather.
    ReloadableProgram mBinCount;
    ReloadableProgram mBinFill;
    ReloadableProgram mScan;
    ReloadableProgram mGather;
    gl::Buffer mGatherParams; // gpu::GatherParams
    gl::Buffer mTiles;        // header + gpu::GatherTile per tile
    gl::Buffer mList;         // photon indices, tile by tile
};

} // namespace ispm
