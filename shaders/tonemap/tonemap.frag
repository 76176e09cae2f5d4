// Tone mapping of the HDR total to display values. Thesis operator: scale by 2^exposure, clamp
// the luminance (0.3 R + 0.6 G + 0.1 B) at luminance_max keeping the hue, divide by luminance_max,
// then gamma. Filmic: the ACES fit of Narkowicz (2015) with luminance_max at ~97% of white.
// Linear: divide by luminance_max and clip per channel.
#include "lib/frame_constants.glsl"
#include "shared/tonemap_data.h"

layout(binding = kUnitHdr) uniform sampler2D uHdr;
layout(std430, binding = kBindingExposure) readonly buffer ExposureBuffer { ExposureData exposure; };

layout(location = 0) out vec4 outColor;

const float kFilmicWhiteScale = 4.0; // ACES(4) = 0.973: luminance_max lands just under white

vec3 applyAcesFit(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

void main() {
    vec3 c = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb * frame.exposureScale;
    float white = frame.luminanceMax > 0.0 ? frame.luminanceMax : exposure.luminanceMax.x;
    uint op = frame.tonemapOperator;
    vec3 display;
    if (op == kTonemapThesis) {
        float y = dot(c, vec3(0.3, 0.6, 0.1));
        float scale = y > white ? white / y : 1.0;
        display = clamp(c * scale / white, 0.0, 1.0);
    } else if (op == kTonemapFilmic) {
        display = applyAcesFit(c / white * kFilmicWhiteScale);
    } else {
        display = clamp(c / white, 0.0, 1.0);
    }
    outColor = vec4(pow(display, vec3(frame.inverseGamma)), 1.0);
}
