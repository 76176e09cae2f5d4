// DenoisePass: the splats' indirect light through `denoise` iterations of an edge-aware a-trous
// filter (steps 1, 2, 4, ... pixels) guided by the viewer G-buffer; 0 passes it through. Its
// output is the frame's indirect AOV.
#pragma once

#include "render/gbuffer.h"
#include "render/pass.h"

#include <array>

namespace ispm {

// `denoise` when set, else log2(min(width, height) / 32) (at least 0).
int computeDenoiseIterations(const Settings& settings, int width, int height);

class DenoisePass final : public Pass {
public:
    DenoisePass(const GBuffer& viewer, const gl::Texture& indirect);
    const char* getName() const override { return "denoise"; }
    void resize(int width, int height) override;
    void execute(const FrameInputs& inputs) override;
    void reloadPrograms(ShaderReloadReport& report) override { mProgram.reloadIfChanged(report); }
    const gl::Texture& getOutput() const { return mTargets[kOutput]; }

private:
    // Two targets to ping-pong between, and the output the last iteration writes.
    static constexpr size_t kOutput = 2;
    const GBuffer& mViewer;
    const gl::Texture& mIndirect;
    ReloadableProgram mProgram;
    gl::VertexArray mVertexArray;
    std::array<gl::Texture, 3> mTargets;
    std::array<gl::Framebuffer, 3> mFramebuffers;
};

} // namespace ispm
