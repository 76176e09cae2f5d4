// Depth blur, second step (DepthBlurPass): a scatter written as a gather. Pixel q sums, over
// every pixel p within the frame's largest radius, p's radiance share times p's disc weight at
// q's distance: exactly what p's disc spreads to q, so the image's sum is kept. Light a disc
// spreads beyond the image lands mirrored at the edge (post_common.glsl): q also gathers around
// its mirror images beyond each edge within reach (exact while the image is wider and taller
// than a disc, 2 x 16 px).
#include "shared/scene_data.h"
#include "shared/post_data.h"

#include "post/post_common.glsl"

layout(binding = kUnitPostAux) uniform sampler2D uSpread;
layout(std430, binding = kBindingPostCocMax) readonly buffer CocMax { uint cocMaxPx; };

layout(location = 0) out vec4 outRadiance;

// What the discs of the pixels within `reach` of point c (inside the image or beyond it) spread
// to c.
vec3 gatherAround(ivec2 c, int reach, ivec2 size) {
    ivec2 lo = max(c - reach, ivec2(0));
    ivec2 hi = min(c + reach, size - 1);
    vec3 sum = vec3(0.0);
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            vec4 spread = texelFetch(uSpread, ivec2(x, y), 0);
            sum += spread.rgb * computeDiscWeight(length(vec2(x - c.x, y - c.y)), spread.a);
        }
    }
    return sum;
}

void main() {
    ivec2 q = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uSpread, 0);
    int reach = int(min(cocMaxPx, uint(ceil(kMaxCocRadiusPx + 0.5))));
    // q, and the points beyond the left/bottom and right/top edges that mirror onto it.
    ivec3 xs = ivec3(q.x, -q.x - 1, 2 * size.x - 1 - q.x);
    ivec3 ys = ivec3(q.y, -q.y - 1, 2 * size.y - 1 - q.y);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < 3; ++j) {
        if (ys[j] + reach < 0 || ys[j] - reach > size.y - 1) continue; // no disc reaches it
        for (int i = 0; i < 3; ++i) {
            if (xs[i] + reach < 0 || xs[i] - reach > size.x - 1) continue;
            sum += gatherAround(ivec2(xs[i], ys[j]), reach, size);
        }
    }
    outRadiance = vec4(sum, 1.0);
}
