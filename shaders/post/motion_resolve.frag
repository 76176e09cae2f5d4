// Motion blur, resolve (MotionBlurPass): the scattered radiance into the output texture.
#include "shared/scene_data.h"
#include "shared/post_data.h"

layout(binding = kUnitPostSource) uniform sampler2D uSource;
layout(std430, binding = kBindingPostScatter) readonly buffer Scattered { float scattered[]; };

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint base = 3u * uint(pixel.y * textureSize(uSource, 0).x + pixel.x);
    outRadiance = vec4(scattered[base], scattered[base + 1u], scattered[base + 2u], 1.0);
}
