// Photon-buffer images: the last frame's bounce and/or result photons drawn as points over the
// scene, read straight from the GPU buffers the passes filled (no read-back of the photons). The
// viewer draws them over its debug views; `render --aov bounce_direction ...` writes them as the
// thesis's photon-buffer figures (direction as RGB, or power).
#pragma once

#include "gl/objects.h"
#include "image/image.h"
#include "render/frame.h"
#include "render/reloadable_program.h"

#include <array>
#include <optional>
#include <string>

namespace ispm {

enum class PhotonPoints { None, Bounce, Result, Both };
inline constexpr std::array<const char*, 4> kPhotonPointsNames = {"none", "bounce", "result",
                                                                  "both"};

// How a point is coloured: `kind` tints bounce photons yellow and result photons cyan, half
// their own hue; `direction` maps the unit direction (the bounce photon's outgoing one, the
// result photon's direction of travel) from [-1, 1] to RGB; `power` shows the photon's RGB power
// in units of the mean luminance power a photon leaves its light with, white at
// kPhotonPowerWhite of them (a photon that kept its power shows mid-grey), gamma 2.2.
enum class PhotonColour { Kind, Direction, Power };
inline constexpr double kPhotonPowerWhite = 2.0;
inline constexpr std::array<const char*, 3> kPhotonColourNames = {"kind", "direction", "power"};

// The `render --aov` photon images: bounce_direction, bounce_power, result_direction,
// result_power; nullopt for any other name.
struct PhotonAov {
    PhotonPoints points = PhotonPoints::Result;
    PhotonColour colour = PhotonColour::Direction;
};
std::optional<PhotonAov> findPhotonAov(const std::string& name);

// 1 / the mean luminance power (W) of the photons the last frame emitted: the lights' power into
// their views over the photons drawn from them. 0 without photons.
double computePhotonPowerScale(const FrameRunner& runner);

class PhotonPointsDrawer {
  public:
    PhotonPointsDrawer();
    // Draws into the bound framebuffer, whose viewport must cover the frame's image (the points
    // use the frame's clipFromWorld); points behind the viewer's visible surface are hidden. How
    // many photons each buffer holds is read on the GPU from the frame's counters.
    void draw(const FrameRunner& runner, PhotonPoints which, PhotonColour colour) const;
    // The AOV image: the tone-mapped frame dimmed to 30% of its display values (or black
    // without `backdrop`), the photons over it (row 0 at the top, RGB in [0, 1]).
    Image renderAov(const FrameRunner& runner, const PhotonAov& aov, bool backdrop = true) const;
    void reloadPrograms(ShaderReloadReport& report) {
        mBounceProgram.reloadIfChanged(report);
        mResultProgram.reloadIfChanged(report);
        mBackdropProgram.reloadIfChanged(report);
    }

  private:
    ReloadableProgram mBounceProgram;
    ReloadableProgram mResultProgram;
    ReloadableProgram mBackdropProgram;
    gl::Buffer mBounceParams; // gpu::PhotonPointsParams
    gl::Buffer mResultParams;
    gl::VertexArray mVertexArray;
};

} // namespace ispm
