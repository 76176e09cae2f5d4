// Temporal accumulation (AccumulatePass): this frame's light mixed into the history with
// weight uWeight (1 / frames of a running mean, or 1 / accumulate).
#include "lib/frame_constants.glsl"

layout(binding = kUnitFilterSource) uniform sampler2D uCurrent;
layout(binding = kUnitHistory) uniform sampler2D uHistory;

layout(location = 0) uniform float uWeight;

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // Alpha too: the direct light's is the pixel's surface coverage (compose.frag).
    vec4 current = texelFetch(uCurrent, pixel, 0);
    vec4 history = texelFetch(uHistory, pixel, 0);
    outRadiance = mix(history, current, uWeight);
}
