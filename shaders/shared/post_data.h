// Post-processing in linear HDR between compose and tone map (app/render/post_pass.cpp): motion
// blur, depth blur and bloom, each an energy-conserving redistribution of the composed radiance.
// Shared by C++ and GLSL: the parameter block, the limits and the thin-lens blur formula.
#ifndef ISPM_POST_DATA_H
#define ISPM_POST_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// Largest depth-blur (circle of confusion) radius: the gather visits (2r + 1)^2 pixels, so the
// cost grows with its square (16 px: 1089 taps a pixel at most).
ISPM_CONST float kMaxCocRadiusPx = 16.0f;
// Longest motion-blur streak: a pixel's light is split into at most this many samples + 1.
ISPM_CONST float kMaxMotionBlurPx = 64.0f;
// Widest bloom kernel (the setting's range): 2r + 1 taps per axis.
ISPM_CONST float kMaxBloomRadiusPx = 64.0f;
// Bloom kernel: a Gaussian truncated at bloom_radius_px = 3 sigma (99.7% of its mass inside).
ISPM_CONST float kBloomSigmasPerRadius = 3.0f;
ISPM_CONST uint kPostGroupSize = 8u; // motion_scatter.comp: 8x8 pixels per work group

// Thin lens of aperture diameter A focused at distance S: a point at depth d (along the view
// axis) images to a blur circle on the sensor of diameter c = A F / (S - F) |d - S| / d (F the
// focal length). The sensor sits at v = S F / (S - F) behind the lens and spans the vertical field
// of view, so one pixel there is 2 v tan(fovY / 2) / H wide; F cancels, and in pixels
//   c / pixel = A |1/d - 1/S| H / (2 tan(fovY / 2)),
// the angle A |1/d - 1/S| the aperture subtends, over a pixel's angle. With the field of view
// fixed, the circle does not depend on the focal length. Inverse distances let d or S be
// infinite (0). Returns the radius c / 2 in pixels, at most kMaxCocRadiusPx.
ISPM_INLINE float computeCocRadiusPx(float apertureM, float inverseDepth, float inverseFocus,
                                     float pixelsPerRadian) {
    float diameterPx = apertureM * abs(inverseDepth - inverseFocus) * pixelsPerRadian;
    return min(0.5f * diameterPx, kMaxCocRadiusPx);
}

// Parameters of the post passes (std140, at kBindingPassParams; one block per draw, bound by
// range).
struct PostParams {
    float bloomThreshold; // luminance W/(m^2 sr)
    float bloomIntensity; // share spread, 0..1
    float bloomRadiusPx;
    float bloomSigmaPx;     // the Gaussian's
    float apertureM;        // depth blur's aperture diameter
    float inverseFocusPerM; // 1 / focus distance
    float pixelsPerRadian;  // H / (2 tan(fovY / 2))
    uint focusAtCentre;     // 1: focus at the image centre's depth
    vec3 viewAxisW;         // unit view axis (depth is measured along it)
    float shutter;          // motion blur's, a fraction of the frame
    uint blurAxis;          // a bloom blur draw's (0: x, 1: y)
    uint addsSource;        // 1: the blur adds the source less the extract (the bloom's last)
    uint padding0;
    uint padding1;
};
ISPM_STATIC_ASSERT_SIZE(PostParams, 64);

// Storage: motion blur's scattered radiance (3 floats a pixel, added with compare-and-swap), and
// depth blur's largest radius this frame (uint pixels, atomicMax), which bounds its gather.
ISPM_CONST int kBindingPostScatter = 23;
ISPM_CONST int kBindingPostCocMax = 24;

// Texture units: the step's input radiance and its helpers.
ISPM_CONST int kUnitPostSource = 25;
ISPM_CONST int kUnitPostAux = 26;
ISPM_CONST int kUnitPostAux2 = 27;

ISPM_NAMESPACE_END

#endif
