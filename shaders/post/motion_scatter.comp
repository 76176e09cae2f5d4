// Motion blur, scatter (MotionBlurPass): each pixel's radiance is split into n equal samples
// along its streak, velocity x shutter centred on the pixel (where the surface it shows was
// while the shutter was open), n = ceil(length) + 1 so neighbouring samples are at most a pixel
// apart; each sample adds its share to the pixel it lands in, kept inside the image. The shares
// sum to the pixel's radiance, so the image's sum is kept (a sample beyond the image lands
// mirrored at its edge). Floats are added with compare-and-swap on their bits (GL 4.5 has no
// float atomics).
#include "shared/scene_data.h"
#include "shared/post_data.h"

#include "lib/viewer_gbuffer.glsl"
#include "post/post_common.glsl"

layout(local_size_x = kPostGroupSize, local_size_y = kPostGroupSize) in;
layout(std140, binding = kBindingPassParams) uniform PostParamsBlock { PostParams params; };
layout(binding = kUnitPostSource) uniform sampler2D uSource;
layout(std430, binding = kBindingPostScatter) buffer Scattered { uint scattered[]; };

void addFloat(uint index, float value) {
    if (value == 0.0) return;
    uint expected = scattered[index];
    while (true) {
        uint desired = floatBitsToUint(uintBitsToFloat(expected) + value);
        uint seen = atomicCompSwap(scattered[index], expected, desired);
        if (seen == expected) break;
        expected = seen;
    }
}

void main() {
    ivec2 size = textureSize(uSource, 0);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, size))) return;
    vec3 radiance = texelFetch(uSource, pixel, 0).rgb;
    vec2 streak = texelFetch(uVelocity, pixel, 0).xy * params.shutter;
    float len = length(streak);
    // A velocity that is not finite (a point at the last eye's plane) does not move.
    if (isnan(len) || isinf(len)) {
        streak = vec2(0.0);
        len = 0.0;
    } else if (len > kMaxMotionBlurPx) {
        streak *= kMaxMotionBlurPx / len;
        len = kMaxMotionBlurPx;
    }
    int n = int(ceil(len)) + 1;
    vec3 share = radiance / float(n);
    for (int i = 0; i < n; ++i) {
        float t = (float(i) + 0.5) / float(n) - 0.5;
        vec2 at = vec2(pixel) + 0.5 + streak * t;
        ivec2 cell = ivec2(floor(at));
        ivec2 target = ivec2(mirrorIndex(cell.x, size.x), mirrorIndex(cell.y, size.y));
        uint base = 3u * uint(target.y * size.x + target.x);
        addFloat(base, share.r);
        addFloat(base + 1u, share.g);
        addFloat(base + 2u, share.b);
    }
}
