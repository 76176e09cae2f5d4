// Picks the white point: the luminance below which kWhitePercentile of the lit pixels lie, and
// moves the adapted white point towards it in log luminance by this frame's weight
// (frame.adaptationWeight = 1 - exp(-dt / eye_adaptation_s), or 1: at once).
#include "lib/frame_constants.glsl"
#include "shared/tonemap_data.h"

layout(local_size_x = 1) in;
layout(std430, binding = kBindingExposure) buffer ExposureBuffer { ExposureData exposure; };

void main() {
    uint total = 0u;
    for (uint b = 0u; b < kLuminanceBins; ++b) total += exposure.histogram[b];
    exposure.counts.x = total;
    float log2White = 0.0; // 1 W/(m^2 sr) when nothing is lit
    if (total > 0u) {
        uint target = uint(ceil(kWhitePercentile * float(total)));
        uint running = 0u;
        for (uint b = 0u; b < kLuminanceBins; ++b) {
            running += exposure.histogram[b];
            if (running >= target) {
                // Upper edge of the bin, so the percentile pixel itself is not clipped.
                float t = float(b + 1u) / float(kLuminanceBins - 1u);
                log2White = mix(kLog2LuminanceMin, kLog2LuminanceMax, t);
                break;
            }
        }
    }
    float target = exp2(log2White);
    float previous = exposure.luminanceMax.x;
    float weight = frame.adaptationWeight;
    float white = target;
    if (weight < 1.0 && previous > 0.0) white = exp2(mix(log2(previous), log2White, weight));
    exposure.luminanceMax = vec4(white, target, 0.0, 0.0);
}
