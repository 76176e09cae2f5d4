// The per-frame uniform block (layout in shared/scene_data.h).
#include "../shared/scene_data.h"

layout(std140, binding = kBindingFrameConstants) uniform FrameConstantsBlock {
    FrameConstants frame;
};

// The eye's ray through image point `point` (pixels from the lower left): the offset from the
// eye to where it crosses the near plane (normalised: its direction). Through eyeOffsetFromClip,
// which keeps the digits however near the near plane (1e-5 of the far plane at most) and however
// far the eye from the origin.
vec3 computeEyeToNear(vec2 point) {
    vec2 ndc = point * frame.inverseImageSizePx * 2.0 - 1.0;
    vec4 offset = frame.eyeOffsetFromClip * vec4(ndc, -1.0, 1.0);
    return offset.xyz / offset.w;
}

// The viewer's pixel that world point `positionW` projects onto; false where it lies behind the
// eye or outside the image.
bool findViewerPixel(vec3 positionW, out ivec2 pixel) {
    pixel = ivec2(0);
    vec4 clip = frame.clipFromWorld * vec4(positionW, 1.0);
    if (clip.w <= 0.0) return false;
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThanEqual(abs(ndc), vec2(1.0)))) return false;
    pixel = min(ivec2((ndc * 0.5 + 0.5) * frame.imageSizePx), ivec2(frame.imageSizePx) - 1);
    return true;
}

// The viewer G-buffer pixel that pixel `p` of a buffer `divisor` times smaller than the image
// stands for (splat_resolution): the middle of its block, inside the image. The splat shades
// it, the filter and the upsample weigh by it.
ivec2 getBlockGBufferPixel(ivec2 p, int divisor) {
    return min(p * divisor + divisor / 2, ivec2(frame.imageSizePx) - 1);
}

// A clip-space position of the image moved into the clip space of a buffer `divisor` times
// smaller, such that the rasteriser samples buffer pixel p exactly at the centre of its
// getBlockGBufferPixel (not at the block's centre, half an image pixel away): coverage is
// tested where the fragment stage shades, so discs of a pixel or two lose nothing.
vec4 toBlockClip(vec4 clip, int divisor) {
    if (divisor <= 1) return clip;
    vec2 image = frame.imageSizePx;
    vec2 reduced = vec2((ivec2(image) + divisor - 1) / divisor);
    // Image pixel x = (ndc + 1) image / 2 must land at buffer pixel (x - divisor / 2 - 0.5) /
    // divisor + 0.5, buffer ndc = 2 pixel / reduced - 1: an affine map, applied before the divide.
    vec2 scale = image / (float(divisor) * reduced);
    vec2 offset = scale + (1.0 - 2.0 * (float(divisor / 2) + 0.5) / float(divisor)) / reduced - 1.0;
    return vec4(clip.xy * scale + offset * clip.w, clip.zw);
}
