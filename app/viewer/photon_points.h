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
    // frame's image size (the points use the frame's clipFromWorld). `counts` says how many
    // photons each buffer holds (PhotonCounts of the same frame).
    void draw(const FrameRunner& runner, const PhotonCounts& counts, PhotonPoints which, int width,
              int height) const;
    void reloadPrograms(ShaderReloadReport& report) {
        mBounceProgram.reloadIfChanged(report);
        mResultProgram.reloadIfChanged(report);
    }

  private:
    ReloadableProgram mBounceProgram;
    ReloadableProgram mResultProgram;
    gl::VertexArray mVertexArray;
};

} // namespace ispm
