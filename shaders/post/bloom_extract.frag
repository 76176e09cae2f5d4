// Bloom, first step (BloomPass): the part of each pixel's radiance that blooms, intensity x the
// share of its luminance above the threshold (hue kept). What it takes is added back blurred.
#include "shared/scene_data.h"
#include "shared/post_data.h"

layout(std140, binding = kBindingPassParams) uniform PostParamsBlock { PostParams params; };
layout(binding = kUnitPostSource) uniform sampler2D uSource;

layout(location = 0) out vec4 outBloom;

void main() {
    vec3 radiance = texelFetch(uSource, ivec2(gl_FragCoord.xy), 0).rgb;
    float luminance = dot(radiance, vec3(0.3, 0.6, 0.1)); // the thesis tone map's weights
    float threshold = params.bloomThreshold;
    float share = luminance > threshold ? (luminance - threshold) / luminance : 0.0;
    outBloom = vec4(radiance * (share * params.bloomIntensity), 1.0);
}
