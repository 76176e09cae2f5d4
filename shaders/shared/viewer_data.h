// Parameters of the viewer's own draws over the window, shared by C++ (app/viewer/) and GLSL
// (shaders/viewer/): each a std140 block at kBindingPassParams.
#ifndef ISPM_VIEWER_DATA_H
#define ISPM_VIEWER_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// blit.frag: one texture of the frame over the scene region (debug_view.cpp).
struct BlitParams {
    vec4 region;    // origin x, y and size in window pixels
    vec4 transform; // x = scale, y = bias, z = 1/gamma (0: none), w = array layer
    uvec4 control;  // x = 1: black where the light view's position.w marks no surface
};
ISPM_STATIC_ASSERT_SIZE(BlitParams, 48);

// reference_view.frag: the reference, side by side, or the error heat map (reference_view.cpp).
ISPM_CONST uint kReferenceModeReference = 0u;
ISPM_CONST uint kReferenceModeSideBySide = 1u;
ISPM_CONST uint kReferenceModeHeatMap = 2u;
struct ReferenceViewParams {
    vec4 region;   // origin x, y and size in window pixels
    vec4 display;  // x = scale 2^stops, y = 1/gamma, z = heat map maximum, w unused
    uvec4 control; // x = mode (kReferenceMode*)
};
ISPM_STATIC_ASSERT_SIZE(ReferenceViewParams, 48);

ISPM_NAMESPACE_END

#endif
