// Flicker over an animated run (bench --flicker N): per pixel, the temporal standard deviation
// of the indirect light over N frames; the figure is their mean divided by the mean indirect
// light, over every surface pixel and over the pixels whose surface point stays farther than a
// given distance from every moving object (the light there should not change at all).
#pragma once

#include "image/image.h"
#include "scene/scene.h"

#include <vector>

namespace ispm {

struct FlickerResult {
    int frames = 0;
    double all = 0.0;   // mean std / mean light, every surface pixel
    double away = 0.0;  // the same over the pixels away from moving objects (0 when none)
    double awayM = 0.0; // the distance that defines "away"
    size_t pixels = 0;  // surface pixels
    size_t awayPixels = 0;
};

class FlickerMeter {
  public:
    explicit FlickerMeter(double awayM) : mAwayM(awayM) {}
    // One frame: its indirect light, the viewer G-buffer's positions (w > 0.5: a surface) and
    // the scene as drawn (the animated instances' boxes are taken from it).
    void addFrame(const Image& indirect, const std::vector<glm::vec4>& positions,
                  const Scene& scene);
    FlickerResult getResult() const;

  private:
    double mAwayM;
    int mFrames = 0;
    std::vector<double> mSum;
    std::vector<double> mSumSquares;
    std::vector<float> mNearestMovingM; // per pixel, over every frame so far
    std::vector<bool> mSurface;
};

} // namespace ispm
