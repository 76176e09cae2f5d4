// The viewer's reference views: the reference alone, a split with the ispm total on the left and
// the reference on the right (same exposure and encoding as the linear views), or the relative
// error |ispm - ref| / (ref + eps) in false colour with its legend bar along the bottom.
#include "shared/scene_data.h"
#include "shared/viewer_data.h"

layout(binding = 0) uniform sampler2D uTotal;
layout(binding = 1) uniform sampler2D uReference; // sum of samples (rgb) and their count (a)

layout(std140, binding = kBindingPassParams) uniform ReferenceViewParamsBlock { ReferenceViewParams params; };

layout(location = 0) out vec4 outColor;

// Radiance added to the reference in the error's denominator so that black reference pixels
// do not saturate the map (the same role as relMSE's epsilon).
const float kErrorEpsilon = 1e-2;
const float kLegendHeightPx = 12.0;
const float kDividerPx = 1.0;

// Blue -> cyan -> green -> yellow -> red: monotonic in lightness up to yellow, readable in print.
vec3 computeFalseColour(float t) {
    const vec3 kStops[5] = vec3[5](vec3(0.0, 0.0, 0.6), vec3(0.0, 0.7, 1.0), vec3(0.1, 0.8, 0.2),
                                   vec3(1.0, 0.9, 0.0), vec3(0.9, 0.0, 0.0));
    float x = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(kStops[i], kStops[i + 1], x - float(i));
}

vec3 readReference(vec2 uv) {
    vec4 s = textureLod(uReference, uv, 0.0);
    return s.rgb / max(s.a, 1.0);
}

vec3 encode(vec3 linear) {
    return pow(max(linear * params.scale, vec3(0.0)), vec3(params.inverseGamma));
}

void main() {
    vec2 local = gl_FragCoord.xy - params.regionOriginPx;
    vec2 uv = local / params.regionSizePx;
    uint mode = params.mode;
    vec3 c;
    if (mode == kReferenceModeReference) {
        c = encode(readReference(uv));
    } else if (mode == kReferenceModeSideBySide) {
        float middle = 0.5 * params.regionSizePx.x;
        if (abs(local.x - middle) < kDividerPx) {
            c = vec3(1.0);
        } else {
            c = encode(local.x < middle ? textureLod(uTotal, uv, 0.0).rgb : readReference(uv));
        }
    } else if (local.y < kLegendHeightPx) {
        c = computeFalseColour(uv.x);
    } else {
        vec3 x = textureLod(uTotal, uv, 0.0).rgb;
        vec3 r = readReference(uv);
        float error = dot(abs(x - r), vec3(1.0)) / (dot(r, vec3(1.0)) + kErrorEpsilon);
        c = computeFalseColour(error / params.heatMapMax);
    }
    outColor = vec4(c, 1.0);
}
