// Parameters of the viewer's own draws over the window, shared by C++ (app/viewer/) and GLSL
// (shaders/viewer/): each a std140 block at kBindingPassParams.
#ifndef ISPM_VIEWER_DATA_H
#define ISPM_VIEWER_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// blit.frag: one texture of the frame over the scene region (debug_view.cpp).
struct BlitParams {
    vec2 regionOriginPx; // in the window
    vec2 regionSizePx;
    float scale;
    float bias;
    float inverseGamma; // 0: none
    float layer;        // the source's array layer
    uint masked;        // 1: black where the light view's position.w marks no surface
    uint padding0;
    uint padding1;
    uint padding2;
};
ISPM_STATIC_ASSERT_SIZE(BlitParams, 48);

// reference_view.frag: the reference, side by side, or the error heat map (reference_view.cpp).
ISPM_CONST uint kReferenceModeReference = 0u;
ISPM_CONST uint kReferenceModeSideBySide = 1u;
ISPM_CONST uint kReferenceModeHeatMap = 2u;
struct ReferenceViewParams {
    vec2 regionOriginPx; // in the window
    vec2 regionSizePx;
    float scale; // 2^stops
    float inverseGamma;
    float heatMapMax; // the heat map's maximum
    uint mode;        // kReferenceMode*
};
ISPM_STATIC_ASSERT_SIZE(ReferenceViewParams, 32);

ISPM_NAMESPACE_END

#endif
