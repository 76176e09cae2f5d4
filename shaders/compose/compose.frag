// Total radiance = direct + indirect + emission, or the background where no surface is.
#include "lib/frame_constants.glsl"

layout(binding = kUnitGBufferFirst + GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = kUnitGBufferFirst + GBUFFER_EMISSION) uniform sampler2D uEmission;
layout(binding = kUnitDirect) uniform sampler2D uDirect;
layout(binding = kUnitIndirect) uniform sampler2D uIndirect;

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (texelFetch(uPosition, pixel, 0).w < 0.5) {
        outRadiance = vec4(frame.background.rgb, 1.0);
        return;
    }
    vec3 radiance = texelFetch(uDirect, pixel, 0).rgb + texelFetch(uIndirect, pixel, 0).rgb +
                    texelFetch(uEmission, pixel, 0).rgb;
    outRadiance = vec4(radiance, 1.0);
}
