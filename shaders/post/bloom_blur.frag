// Bloom, blur (BloomPass): one axis of a Gaussian truncated at the radius (3 sigma), weights
// normalised to sum to one. Beyond the image the source is mirrored (half-sample symmetric):
// with a symmetric kernel the gather then equals the scatter that reflects at the edges, so
// every source pixel's weights land inside the image and sum to one. params.blurAxis: 0 x,
// 1 y; params.addsSource = 1: the output is the source minus what bloomed plus the blurred bloom.
#include "shared/scene_data.h"
#include "shared/post_data.h"

layout(std140, binding = kBindingPassParams) uniform PostParamsBlock { PostParams params; };
layout(binding = kUnitPostSource) uniform sampler2D uSource;
layout(binding = kUnitPostAux) uniform sampler2D uBlurInput;
layout(binding = kUnitPostAux2) uniform sampler2D uBloom;

layout(location = 0) out vec4 outRadiance;

#include "post/post_common.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uBlurInput, 0);
    int axis = int(params.blurAxis);
    int n = axis == 0 ? size.x : size.y;
    int at = axis == 0 ? pixel.x : pixel.y;
    int reach = int(ceil(min(params.bloomRadiusPx, kMaxBloomRadiusPx)));
    float sigma = max(params.bloomSigmaPx, 1e-3);
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int i = -reach; i <= reach; ++i) {
        float w = exp(-0.5 * float(i * i) / (sigma * sigma));
        ivec2 p = pixel;
        p[axis] = mirrorIndex(at + i, n);
        sum += w * texelFetch(uBlurInput, p, 0).rgb;
        weightSum += w;
    }
    vec3 blurred = sum / weightSum;
    if (params.addsSource == 1u) {
        vec3 source = texelFetch(uSource, pixel, 0).rgb;
        blurred += source - texelFetch(uBloom, pixel, 0).rgb;
    }
    outRadiance = vec4(blurred, 1.0);
}
