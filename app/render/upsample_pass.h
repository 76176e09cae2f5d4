// UpsamplePass: the filtered indirect light from the splat buffer (`splat_resolution` 1/2, 1/4)
// back to the image's resolution by a joint-bilateral filter on the viewer G-buffer: each pixel
// weighs the four buffer pixels around it by distance, by how far their surface turns from its own
// and by how far their point lies off its plane (read from DenoisePass's guide), so edges stay
// sharp; the light comes as irradiance and is multiplied by the pixel's own reflectance. At full
// resolution it passes the light through. In radius_mode density it adds the caustic photons'
// light, splatted apart at the image's resolution (SplatPass::getCaustics). Its output is the
// frame's indirect AOV.
#pragma once

#include "render/fullscreen.h"
#include "render/gbuffer.h"
#include "render/pass.h"

#include <shared/scene_data.h>

namespace ispm {

class UpsamplePass final : public Pass {
  public:
    // `filtered` and `guide`: DenoisePass's output and guide.
    UpsamplePass(const GBuffer& viewer, const gl::Texture& filtered, const gl::Texture& guide,
                 const gl::Texture& caustics);
    const char* getName() const override { return "upsample"; }
    void resize(int width, int height) override { mTarget.resize(width, height); }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override { mPrograms.reloadIfChanged(report); }
    const gl::Texture& getOutput() const { return mTarget.getTexture(); }

  private:
    const GBuffer& mViewer;
    const gl::Texture& mFiltered;
    const gl::Texture& mGuide;
    const gl::Texture& mCaustics;
    ProgramVariants mPrograms; // caustics added or not, filtered or not
    gl::Buffer mParams{"upsample parameters", sizeof(gpu::FilterParams)};
    gl::VertexArray mVertexArray;
    ColorTarget mTarget;
};

} // namespace ispm
