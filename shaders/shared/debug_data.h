// The interfaces of shaders/debug/, shared by C++ and GLSL: closest-hit queries for a batch of
// rays through the scene's BVH (tests against the CPU traversal, debug tools) and the photon
// buffers drawn as points (viewer, `render --aov bounce_direction ...`).
#ifndef ISPM_DEBUG_DATA_H
#define ISPM_DEBUG_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// Storage bindings above every product binding (shared/*.h), so a query can run with the
// frame's buffers still bound.
ISPM_CONST int kBindingDebugRays = 21;    // DebugRay per ray
ISPM_CONST int kBindingDebugResults = 22; // uvec4 per ray: x = 1 on a hit else 0, y = global
                                          // triangle, z = instance, w = floatBitsToUint(t); on
                                          // a miss y, z are 0 and t is the ray's tMax
// One ray per invocation; 64 is a whole number of SIMD groups on current GPUs (32 or 64 wide).
ISPM_CONST uint kTraceRaysGroupSize = 64u;

struct DebugRay {
    vec4 originTMax; // xyz world-space origin, w = tMax (world-space distance)
    vec4 direction;  // xyz world-space unit direction, w unused
};
ISPM_STATIC_ASSERT_SIZE(DebugRay, 32);

// Parameters of trace_rays.comp (std140, at kBindingPassParams).
struct TraceRaysParams {
    uint rayCount; // the last group runs past the end of the rays
    uint padding0;
    uint padding1;
    uint padding2;
};
ISPM_STATIC_ASSERT_SIZE(TraceRaysParams, 16);

// debug/photon_points.vert: one kind of photon as points (render/photon_points.cpp).
ISPM_CONST uint kPhotonColourKind = 0u;      // the kind's tint, half the photon's hue
ISPM_CONST uint kPhotonColourDirection = 1u; // unit direction [-1, 1] -> RGB [0, 1]
ISPM_CONST uint kPhotonColourPower = 2u;     // RGB power x powerScale, then ^inverseGamma
struct PhotonPointsParams {
    vec3 tint; // of this kind of photon
    float pointSizePx;
    float powerScale;   // 1/W: white at 1
    float inverseGamma; // of power colours
    uint colouring;     // kPhotonColour*
    uint padding0;
};
ISPM_STATIC_ASSERT_SIZE(PhotonPointsParams, 32);

ISPM_NAMESPACE_END

#endif
