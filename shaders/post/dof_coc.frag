// Depth blur, first step (DepthBlurPass): each pixel's circle of confusion (thin lens,
// computeCocRadiusPx in shared/post_data.h) from its depth along the view axis, its radiance
// divided by the disc's total weight inside the image (rgb), the radius (a), and the largest
// radius of the frame (the gather's reach).
#include "lib/frame_constants.glsl"
#include "shared/post_data.h"

#include "lib/viewer_gbuffer.glsl"
#include "post/post_common.glsl"

layout(std140, binding = kBindingPassParams) uniform PostParamsBlock { PostParams params; };
layout(binding = kUnitPostSource) uniform sampler2D uSource;
layout(std430, binding = kBindingPostCocMax) buffer CocMax { uint cocMaxPx; };

layout(location = 0) out vec4 outSpread;

// 1 / depth along the view axis at `pixel`; 0 (infinitely far) where no surface is.
float getInverseDepth(ivec2 pixel) {
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) return 0.0;
    float depth = dot(position.xyz - frame.cameraPosW, params.viewAxisW);
    // Visible points lie beyond the near plane; the guard keeps a degenerate one finite.
    return 1.0 / max(depth, 1e-6);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uSource, 0);
    float inverseFocus = params.focusAtCentre != 0u ? getInverseDepth(size / 2) : params.inverseFocusPerM;
    float radius = computeCocRadiusPx(params.apertureM, getInverseDepth(pixel), inverseFocus,
                                      params.pixelsPerRadian);
    int reach = int(ceil(radius + 0.5));
    float total = 0.0; // the whole disc: what lands beyond the image is mirrored back
    for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx)
            total += computeDiscWeight(length(vec2(dx, dy)), radius);
    }
    atomicMax(cocMaxPx, uint(reach));
    // total >= the pixel's own weight, min(1, radius + 0.5) >= 0.5: no division by zero.
    outSpread = vec4(texelFetch(uSource, pixel, 0).rgb / total, radius);
}
