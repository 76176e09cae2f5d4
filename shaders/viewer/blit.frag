// The viewer's debug view: one texture of the frame stretched over the scene region. Display
// values pass through; linear values and G-buffer channels are scaled, biased and gamma-encoded.
#include "shared/scene_data.h"
#include "shared/viewer_data.h"

#ifdef TEXTURE_ARRAY
layout(binding = 0) uniform sampler2DArray uSource;
// A light view's channels other than position hold values only where position.w marks a surface
// (the light views clear position and depth alone): params.masked = 1 shows black
// elsewhere.
layout(binding = 1) uniform sampler2DArray uPosition;
#else
layout(binding = 0) uniform sampler2D uSource;
#endif

layout(std140, binding = kBindingPassParams) uniform BlitParamsBlock { BlitParams params; };

layout(location = 0) out vec4 outColor;

void main() {
    vec2 uv = (gl_FragCoord.xy - params.regionOriginPx) / params.regionSizePx;
#ifdef TEXTURE_ARRAY
    vec3 c = textureLod(uSource, vec3(uv, params.layer), 0.0).rgb;
    if (params.masked != 0u && textureLod(uPosition, vec3(uv, params.layer), 0.0).w < 0.5) c = vec3(0.0);
#else
    vec3 c = textureLod(uSource, uv, 0.0).rgb;
#endif
    c = c * params.scale + params.bias;
    if (params.inverseGamma > 0.0) c = pow(max(c, vec3(0.0)), vec3(params.inverseGamma));
    outColor = vec4(c, 1.0);
}
