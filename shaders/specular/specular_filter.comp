// Glossy reflections blurred by their lobe: specular_trace.comp leaves what each pixel sees in
// its mirror and glass rays, with (alpha) the spread in pixels of the one mirror ray it traced
// for a glossy lobe (a Phong exponent from kSpecularTraceMinExponent on, not glass): the lobe's
// angular spread, 1 / sqrt(e) per axis, at the hit's distance, seen from the eye. Each such
// pixel takes the Gaussian mean of that light over the glossy pixels of its own surface within
// three spreads (normal and plane tests of the indirect-light filter), which stands for the
// lobe's many directions, as the references average them; glass and near-perfect mirrors (a
// spread under half a pixel) keep their own ray. The result is added to the composed image.
#include "lib/frame_constants.glsl"
#include "lib/gbuffer_filter.glsl"
#include "shared/specular_data.h"

layout(local_size_x = kSpecularGroupSize, local_size_y = kSpecularGroupSize) in;
layout(binding = 0, rgba32f) uniform image2D uTotal;
layout(binding = kUnitFilterSource) uniform sampler2D uSpecularLight;

// Taps per axis on each side of the pixel; a tap every 3/4 spread reaches three spreads.
const int kTapsPerSide = 4;
const float kTapsPerSpread = 4.0 / 3.0;
// The widest spread the filter follows, in pixels (taps 12 pixels apart at most).
const float kMaxSpreadPx = 16.0;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.imageSizePx);
    if (any(greaterThanEqual(pixel, size))) return;
    vec4 own = texelFetch(uSpecularLight, pixel, 0);
    vec3 light = own.rgb;
    float spread = min(own.a, kMaxSpreadPx);
    if (spread >= 0.5) {
        vec4 position = texelFetch(uPosition, pixel, 0);
        vec3 n = texelFetch(uNormal, pixel, 0).xyz;
        float step = max(spread / kTapsPerSpread, 1.0);
        float planeScale = computePlaneScale(pixel, position.xyz, 1) / step;
        vec3 sum = vec3(0.0);
        float weights = 0.0;
        for (int dy = -kTapsPerSide; dy <= kTapsPerSide; ++dy) {
            for (int dx = -kTapsPerSide; dx <= kTapsPerSide; ++dx) {
                vec2 offset = vec2(dx, dy) * step;
                ivec2 q = pixel + ivec2(round(offset));
                if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
                vec4 tap = texelFetch(uSpecularLight, q, 0);
                if (tap.a <= 0.0) continue; // not a traced glossy pixel
                float w = exp(-0.5 * dot(offset, offset) / (spread * spread)) *
                          weighTap(q, n, position.xyz, planeScale);
                sum += w * tap.rgb;
                weights += w;
            }
        }
        if (weights > 0.0) light = sum / weights;
    }
    if (all(equal(light, vec3(0.0)))) return;
    vec4 total = imageLoad(uTotal, pixel);
    imageStore(uTotal, pixel, vec4(total.rgb + light, total.a));
}
