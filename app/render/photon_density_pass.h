// PhotonDensityPass (radius_mode = density): after tracing, every result photon gets the radius of
// the disc that holds about `splat_neighbours` photons around it, estimated on the GPU from the
// result photons themselves (hashed grids of cells at several sizes, photon_density.comp). Dense
// places splat small and sharp, sparse ones large enough that discs still overlap. In the travel
// modes it sets the travel radius instead, so the splat reads every mode's radius from one place.
#pragma once

#include "render/gbuffer.h"
#include "render/pass.h"
#include "render/photon_buffers.h"
#include "render/zero_fill.h"
#include "scene/scene.h"

#include <shared/photon_data.h>

namespace ispm {

// The radius of a disc holding k photons if all `photons` were spread evenly over the scene's
// surface. The finest grid cell is a sixteenth of it, so that photons aimed at a small part of
// the scene still find their level; radii stop at 4 times it (radius_max's derived value), so a
// photon alone in a dark place splats wide but not across the scene.
float computeEvenRadius(double surfaceAreaM2, int photons, int neighbours);
// radius_max's derived value in radius_mode density (before radius_scale): 4 times the even
// radius.
float computeDensityRadiusMax(double surfaceAreaM2, int photons, int neighbours);

// photon_order.comp's parameters for a scene within `bounds`: its grid spans them; the counts
// and the order at uint countsAt and orderAt of the density cells.
gpu::OrderParams makeOrderParams(const Aabb& bounds, size_t countsAt, size_t orderAt);

class PhotonDensityPass final : public Pass {
  public:
    // `viewer`: the viewer G-buffer (surface_ends looks up where the discs lie).
    PhotonDensityPass(PhotonBuffers& buffers, const GBuffer& viewer);
    const char* getName() const override { return "density"; }
    void execute(const FrameInputs& inputs) override;
    // Stages that each run over every photon before the next: 2 in radius_mode density (count
    // into the table, then radii), else 1 (travel radii), 2 with widen_strong (the lights' power
    // first).
    static uint32_t getStageCount(const FrameSettings& settings);
    // Slice `slice` of `slices` of stage `stage` (a frame drawn in slices); execute() runs every
    // stage's slices in order.
    void executeSlice(const FrameInputs& inputs, uint32_t stage, uint32_t slice, uint32_t slices);
    void reloadPrograms(ShaderReloadReport& report) override {
        mPrograms.reloadIfChanged(report);
        mOrderPrograms.reloadIfChanged(report);
        mDiscDraws.reloadIfChanged(report);
        mZeroFill.reloadIfChanged(report);
    }
    // Per result photon: its disc's clip lines and box extents (shared/splat_clip.h), written
    // with splat_clip.
    const gl::Buffer& getClip() const { return mClip; }
    // The caustic photons in view (radius_mode density), at getCausticOffset() bytes into this
    // buffer (after the table): an indexed draw command whose instance count the radius stage
    // sets, then their indices (bound at kBindingCausticList for splat.vert).
    const gl::Buffer& getCausticList() const { return mCells; }
    size_t getCausticOffset() const { return mCausticOffset; }
    // radius_mode density: the discs the splat draws (photons in view that keep a disc of their
    // own, not caustic), in the same buffer at this many bytes: their count (x of a uvec4), then
    // their photons' indices (bound at kBindingDiscList for splat.vert). The last stage rewrites
    // the splat's draw commands (PhotonBuffers::getSplatDraws) over them.
    size_t getDiscOffset() const { return mDiscOffset; }
    // splat_clip (radius_mode density): the stored photons' indices in the order the radius
    // stage took them (photon_order.comp), at this many bytes into getCausticList()'s buffer;
    // 0 without splat_clip.
    size_t getOrderOffset() const { return mOrderOffset; }
    size_t getGpuBytes() const {
        return mCells.getSize() + mClip.getSize() + mLightPower.getSize();
    }

  private:
    // Travel modes: each photon's travel (or path-density) radius, 0 where its disc cannot
    // reach the view; the others count in view.
    void setTravelRadii(const FrameInputs& inputs, glm::uvec2 slice);
    // Over the stored photons, or slice.x of slice.y of them.
    void dispatch(glm::uvec2 slice) const;

    PhotonBuffers& mBuffers;
    const GBuffer& mViewer;
    // widen_strong: each light's stored photons and power, for setTravelRadii.
    void sumLightPower(const FrameInputs& inputs, glm::uvec2 slice);
    // Uploads `params` and runs its travel stage (params.stage) over its slice.
    void runTravelStage(const FrameInputs& inputs, const gpu::DensityParams& params);
    void useStage(uint32_t stage, const FrameSettings& settings);
    // surface_ends: whether `stage` divides each photon's power by its disc's share on a
    // surface (the radius stage, the travel modes' cull; not with splat_clip).
    static bool measuresSurfaceEnds(uint32_t stage, const FrameSettings& settings);
    void reserveClip(); // mClip, one entry per result photon
    // splat_clip: the stored photons' spatial order for the radius stage (photon_order.comp),
    // its counts at uint countsAt of mCells, the indices at orderAt.
    void sortPhotons(const FrameInputs& inputs, size_t countsAt, size_t orderAt);

    // By stage (DENSITY_STAGE), CLIP_DISCS, WIDEN_STRONG, MERGE_DISCS, SURFACE_ENDS.
    ProgramVariants mPrograms;
    ProgramVariants mOrderPrograms; // by stage (ORDER_STAGE)
    ReloadableProgram mDiscDraws;   // photon_prepare.comp's stage kPrepareStageDiscDraws
    gl::Buffer mPrepareParams;      // gpu::PrepareParams of that stage
    ZeroFill mZeroFill;             // clears the table each frame
    gl::Buffer mParams;             // gpu::DensityParams
    gl::Buffer mOrderParams;        // gpu::OrderParams
    gl::Buffer mCells;              // the hashed grid (density radii), the caustic list, the order
    gl::Buffer mLightPower;         // widen_strong: per light its stored photons and power
    gl::Buffer mClip;
    size_t mCausticOffset = 0;
    size_t mDiscOffset = 0;
    size_t mOrderOffset = 0;
};

} // namespace ispm
