// The filter guide (denoise/filter_input.frag): per splat buffer pixel, the surface of the
// G-buffer pixel it stands for, read by the edge-aware filter's and the upsample's taps in one
// fetch of a texture the buffer's size. RGBA32F: the position in xyz, and in w the normal as an
// octahedral map of kGuideAxisBits bits an axis, packed into a whole number below 2^24 (which a
// float holds exactly, so no bit pattern can become a NaN or a flushed denormal), or
// kGuideNoSurface where no surface is.
#ifndef ISPM_FILTER_GUIDE_H
#define ISPM_FILTER_GUIDE_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

ISPM_CONST uint kGuideAxisBits = 12u;
ISPM_CONST float kGuideAxisSteps = 4095.0f; // 2^kGuideAxisBits - 1
ISPM_CONST float kGuideNoSurface = -1.0f;

// 1 or -1 (1 at 0), per component.
ISPM_INLINE vec2 getSignNotZero(vec2 v) {
    return vec2(v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f);
}

// A unit normal's code: a whole number in [0, 2^(2 kGuideAxisBits)).
ISPM_INLINE float encodeGuideNormal(vec3 n) {
    vec2 p = vec2(n.x, n.y) / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z < 0.0f) p = (vec2(1.0f) - abs(vec2(p.y, p.x))) * getSignNotZero(p);
    vec2 q = round((p * 0.5f + vec2(0.5f)) * kGuideAxisSteps);
    return q.x * (kGuideAxisSteps + 1.0f) + q.y;
}

ISPM_INLINE vec3 decodeGuideNormal(float code) {
    float y = mod(code, kGuideAxisSteps + 1.0f);
    vec2 p = vec2((code - y) / (kGuideAxisSteps + 1.0f), y) / kGuideAxisSteps * 2.0f - vec2(1.0f);
    vec3 n = vec3(p.x, p.y, 1.0f - abs(p.x) - abs(p.y));
    if (n.z < 0.0f) {
        vec2 folded = (vec2(1.0f) - abs(vec2(n.y, n.x))) * getSignNotZero(vec2(n.x, n.y));
        n = vec3(folded.x, folded.y, n.z);
    }
    return normalize(n);
}

ISPM_NAMESPACE_END

#endif
