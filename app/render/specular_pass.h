// SpecularPass: what the camera sees in mirrors and glass. Every viewer pixel on a mirror-like
// lobe (Phong exponent >= kSpecularTraceMinExponent) or a transmissive surface traces a
// reflected and a refracted ray through the BVH, `specular_depth` levels deep, shades each hit
// with direct light (shadow rays) and the indirect light of the visible pixel showing the same
// point (else the view's ambient estimate), and adds the result into the composed image in
// place, a glossy lobe's ray blurred over its surface by the lobe's spread
// (specular/specular_filter.comp). Other pixels are left as they were.
#pragma once

#include "gl/objects.h"
#include "render/gbuffer.h"
#include "render/pass.h"
#include "render/reloadable_program.h"

namespace ispm {

class SpecularPass final : public Pass {
  public:
    // `indirect`: the indirect light of the viewer's pixels (accumulated), read at the pixels
    // the rays' hits reproject onto; `total`: the composed image, added to.
    SpecularPass(const GBuffer& viewer, const gl::Texture& indirect, const gl::Texture& total);
    const char* getName() const override { return "specular"; }
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override {
        mAmbientProgram.reloadIfChanged(report);
        mProgram.reloadIfChanged(report);
        mFilter.reloadIfChanged(report);
    }
    // Whether the pass has anything to do this frame: specular_depth and bounces > 0, and the
    // scene has a surface it traces (GpuScene::hasTracedSpecular).
    static bool isOn(const FrameSettings& settings, const GpuScene& scene);

  private:
    const GBuffer& mViewer;
    const gl::Texture& mIndirect;
    const gl::Texture& mTotal;
    ReloadableProgram mAmbientProgram;
    ProgramVariants mProgram; // by the scene's ray tests (GpuScene::getRayDefines)
    ReloadableProgram mFilter;
    gl::Buffer mParams;
    gl::Texture mAmbient; // 1x1: the view's indirect light per unit reflectance
    gl::Texture mLight;   // what each pixel's rays see; alpha: a glossy ray's spread (px)
};

} // namespace ispm
