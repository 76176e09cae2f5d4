// The reference's light tracer (reference_method = light): paths leave the lights, and every
// vertex on a diffuse or glossy surface is connected to the camera and added to the pixel it
// projects into. Parameters and the splat buffer's binding, shared by C++ (ReferencePass) and
// GLSL (reference/light_trace.comp, reference/light_resolve.comp).
#ifndef ISPM_LIGHT_TRACE_DATA_H
#define ISPM_LIGHT_TRACE_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// Which estimator `--mode reference` runs (setting reference_method).
ISPM_CONST uint kReferencePath = 0u;  // camera paths with next-event estimation (default)
ISPM_CONST uint kReferenceLight = 1u; // light paths connected to the camera (sees caustics)

// std140, at kBindingPassParams.
struct LightTraceParams {
    uint sampleIndex;
    uint bounces;
    uint seed;
    uint pathCount;    // light paths this sample
    float rayFloorM;   // ray offset floor
    float pixelAreaM2; // area of one pixel on the image plane at 1 m from the eye
    float padding0;
    float padding1;
    vec3 cameraAxisW; // unit view direction
    float padding2;
    // The scene's bounds' centre and the radius enclosing them: the sun's paths start on a disc
    // of this radius facing the sun.
    vec3 sceneCentreW;
    float sceneRadiusM;
};
ISPM_STATIC_ASSERT_SIZE(LightTraceParams, 64);

// Storage buffer: three floats (rgb, W/(m^2 sr) summed over this sample's paths) per pixel,
// row-major from the image's row 0 as the accumulation image stores it. Added to with a
// compare-and-swap loop on the float's bits (no float atomics needed).
ISPM_CONST int kBindingLightSplat = 27;

ISPM_NAMESPACE_END

#endif
