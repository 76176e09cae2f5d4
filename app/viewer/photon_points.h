// The photon debug views: the last frame's bounce and/or result photons drawn as points over the
// scene region, read straight from the GPU buffers the passes filled (no read-back).
#pragma once

#include "gl/objects.h"
#include "render/frame.h"
#include "render/reloadable_program.h"

namespace ispm {

enum class PhotonPoints { None, Bounce, Result, Both };

class PhotonPointsDrawer {
  public:
    PhotonPointsDrawer();
    // Draws over the default framebuffer's region [0, width) x [0, height), which must be the
    // frame's image size (the points use the frame's clipFromWorld). How many photons each
    // buffer holds is read on the GPU from the frame's counters: no read-back.
    void draw(const FrameRunner& runner, PhotonPoints which, int width, int height) const;
    void reloadPrograms(ShaderReloadReport& report) {
        mBounceProgram.reloadIfChanged(report);
        mResultProgram.reloadIfChanged(report);
    }

  private:
    ReloadableProgram mBounceProgram;
    ReloadableProgram mResultProgram;
    gl::Buffer mBounceParams; // gpu::PhotonPointsParams
    gl::Buffer mResultParams;
    gl::VertexArray mVertexArray;
};

} // namespace ispm
