// Builds the log2-luminance histogram of the HDR image (luminance 0.3 R + 0.6 G + 0.1 B, as the
// thesis operator uses).
#include "shared/tonemap_data.h"
#include "shared/scene_data.h"

layout(local_size_x = kExposureGroupSize, local_size_y = kExposureGroupSize) in;
layout(binding = kUnitHdr) uniform sampler2D uHdr;
layout(std430, binding = kBindingExposure) buffer ExposureBuffer { ExposureData exposure; };

shared uint sHistogram[kLuminanceBins];

void main() {
    uint local = gl_LocalInvocationIndex;
    for (uint b = local; b < kLuminanceBins; b += kExposureGroupSize * kExposureGroupSize) {
        sHistogram[b] = 0u;
    }
    barrier();
    ivec2 size = textureSize(uHdr, 0);
    ivec2 first = ivec2(gl_GlobalInvocationID.xy) * int(kExposurePixelsPerSide);
    for (int dy = 0; dy < int(kExposurePixelsPerSide); ++dy) {
        for (int dx = 0; dx < int(kExposurePixelsPerSide); ++dx) {
            ivec2 pixel = first + ivec2(dx, dy);
            if (any(greaterThanEqual(pixel, size))) continue;
            vec3 c = texelFetch(uHdr, pixel, 0).rgb;
            float y = dot(c, vec3(0.3, 0.6, 0.1));
            if (y > exp2(kLog2LuminanceMin)) {
                float t = (log2(y) - kLog2LuminanceMin) / (kLog2LuminanceMax - kLog2LuminanceMin);
                uint bin = uint(clamp(t, 0.0, 1.0) * float(kLuminanceBins - 1u));
                atomicAdd(sHistogram[bin], 1u);
            }
        }
    }
    barrier();
    for (uint b = local; b < kLuminanceBins; b += kExposureGroupSize * kExposureGroupSize) {
        if (sHistogram[b] > 0u) atomicAdd(exposure.histogram[b], sHistogram[b]);
    }
}
