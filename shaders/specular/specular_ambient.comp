// The view's ambient estimate for specular_trace.comp, once a frame in one work group: the mean
// indirect light per unit diffuse reflectance over kAmbientGrid^2 visible pixels that show a
// diffuse surface the specular pass does not trace (E / pi of the view's average indirect
// irradiance). A hit that reprojects onto no visible pixel is lit by its diffuse reflectance
// times this. Written to a 1x1 image that the trace reads.
#include "lib/frame_constants.glsl"
#include "shared/specular_data.h"

#include "lib/viewer_gbuffer.glsl"
layout(binding = kUnitIndirect) uniform sampler2D uIndirect;

layout(local_size_x = kSpecularGroupSize, local_size_y = kSpecularGroupSize) in;
layout(binding = kSpecularAmbientImage, rgba32f) writeonly uniform image2D uAmbient;

// Pixels sampled per axis: 256 samples of already smoothed splats average to a few percent.
const uint kAmbientGrid = 16u;
const uint kGroupInvocations = kSpecularGroupSize * kSpecularGroupSize;
// Pixels darker in diffuse reflectance than this are left out: dividing their indirect light
// by it would magnify the splats' noise.
const float kMinAmbientReflectance = 0.02;
shared vec4 sAmbient[kGroupInvocations]; // rgb = sum of indirect / diffuse, a = samples

void main() {
    uint local = gl_LocalInvocationIndex;
    vec4 sum = vec4(0.0);
    for (uint i = local; i < kAmbientGrid * kAmbientGrid; i += kGroupInvocations) {
        vec2 cell = (vec2(i % kAmbientGrid, i / kAmbientGrid) + 0.5) / float(kAmbientGrid);
        ivec2 pixel = ivec2(cell * frame.imageSizePx);
        if (texelFetch(uPosition, pixel, 0).w < 0.5) continue;
        if (isMirrorLobe(texelFetch(uSpecular, pixel, 0)) ||
            isTransmissive(texelFetch(uTransmissive, pixel, 0))) {
            continue;
        }
        vec3 diffuse = texelFetch(uDiffuse, pixel, 0).rgb;
        if (min(diffuse.r, min(diffuse.g, diffuse.b)) < kMinAmbientReflectance) continue;
        sum += vec4(texelFetch(uIndirect, pixel, 0).rgb / diffuse, 1.0);
    }
    sAmbient[local] = sum;
    barrier();
    if (local != 0u) return;
    vec4 total = vec4(0.0);
    for (uint i = 0u; i < kGroupInvocations; ++i)
        total += sAmbient[i];
    imageStore(uAmbient, ivec2(0), vec4(total.a > 0.0 ? total.rgb / total.a : vec3(0.0), 1.0));
}
