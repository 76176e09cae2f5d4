// Rendering helpers for image tests: one frame of a scene to a CPU image, and golden comparison
// that writes the actual and diff images beside the build when it fails.
#pragma once

#include "image/image.h"
#include "render/frame.h"
#include "scene/scene.h"

#include <string>

namespace ispm::test {

Image renderAov(const Scene& scene, const Settings& settings, Aov aov);

// The mean of `spp` samples of the reference (`method` path or light, reference_method) at
// sizePx x sizePx, light cut at `bounces`.
Image renderReference(const Scene& scene, const char* method, int sizePx, int spp, int bounces);

// The reference path tracer's indirect light: reference(bounces) - reference(0), both at `spp`.
Image renderReferenceIndirect(const Scene& scene, const Settings& settings, int spp);

// The largest difference over pixels and channels between a and b, relative to b's mean (an
// expectation fails when b is black: nothing to compare).
double computeMaxRelativeDifference(const Image& a, const Image& b);

struct GoldenThresholds {
    float pixelTolerance;      // a pixel fails when any channel differs by more
    double maxMeanAbsError;    // over all channels
    double maxFailingFraction; // of pixels
};

// Compares with tests/goldens/<name>.png; ISPM_UPDATE_GOLDENS=1 rewrites the golden instead.
void expectMatchesGolden(const Image& actual, const std::string& name, const GoldenThresholds& t);

} // namespace ispm::test
