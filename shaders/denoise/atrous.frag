// One iteration of the edge-aware a-trous filter on the indirect light (Dammertz et al. 2010):
// a 5x5 B3-spline kernel with holes of `step` pixels, each tap weighted down where the surface
// turns (normals) or steps away from the pixel's plane (positions, in pixel footprints). The
// first iteration divides the light by the diffuse reflectance, so the filter smooths irradiance
// and keeps texture and colour edges; the last multiplies it back.
#include "lib/frame_constants.glsl"

layout(binding = kUnitGBufferFirst + GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = kUnitGBufferFirst + GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = kUnitGBufferFirst + GBUFFER_DIFFUSE) uniform sampler2D uDiffuse;
layout(binding = kUnitFilterSource) uniform sampler2D uSource;

layout(location = 0) uniform ivec4 uIteration; // x = step (px), y = 1: demodulate the input,
                                               // z = 1: modulate the output, w = image pixels per
                                               // filtered pixel (splat_resolution)

layout(location = 0) out vec4 outRadiance;

// Normal weight cos^64 (10 degrees apart halves a tap), as six squarings.
float weighNormals(float cosAngle) {
    float w = max(cosAngle, 0.0);
    w *= w;
    w *= w;
    w *= w;
    w *= w;
    w *= w;
    return w * w;
}
const float kPlaneFootprints = 1.0; // off-plane distance, in pixel footprints x step, of e^-1
const float kMinReflectance = 0.02; // demodulation floor (black surfaces keep their light)

// The viewer G-buffer pixel a filtered pixel stands for: the middle of its block (splat.frag).
ivec2 getGBufferPixel(ivec2 pixel) {
    int divisor = uIteration.w;
    return min(pixel * divisor + divisor / 2, ivec2(frame.imageSize.xy) - 1);
}

vec3 getReflectance(ivec2 g) { return max(texelFetch(uDiffuse, g, 0).rgb, vec3(kMinReflectance)); }

vec3 readSource(ivec2 pixel, ivec2 g) {
    vec3 c = texelFetch(uSource, pixel, 0).rgb;
    return uIteration.y == 1 ? c / getReflectance(g) : c;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 g = getGBufferPixel(pixel);
    vec4 position = texelFetch(uPosition, g, 0);
    vec3 centre = readSource(pixel, g);
    if (position.w < 0.5) {
        outRadiance = vec4(centre, 1.0);
        return;
    }
    ivec2 size = textureSize(uSource, 0);
    ivec2 imageSize = ivec2(frame.imageSize.xy);
    vec3 n = texelFetch(uNormal, g, 0).xyz;
    // A filtered pixel's footprint on its surface: the distance to its neighbour's point.
    ivec2 beside = g + ivec2(g.x + uIteration.w < imageSize.x ? uIteration.w : -uIteration.w, 0);
    vec4 besidePosition = texelFetch(uPosition, clamp(beside, ivec2(0), imageSize - 1), 0);
    float footprint = besidePosition.w >= 0.5 ? length(besidePosition.xyz - position.xyz) : 1e30;
    float planeScale = 1.0 / max(kPlaneFootprints * footprint * float(uIteration.x), 1e-30);
    const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = pixel + ivec2(dx, dy) * uIteration.x;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            ivec2 qg = getGBufferPixel(q);
            vec4 qPosition = texelFetch(uPosition, qg, 0);
            if (qPosition.w < 0.5) continue;
            vec3 qNormal = texelFetch(uNormal, qg, 0).xyz;
            float w = kB3[abs(dx)] * kB3[abs(dy)];
            w *= weighNormals(dot(n, qNormal));
            w *= exp(-abs(dot(n, qPosition.xyz - position.xyz)) * planeScale);
            sum += w * readSource(q, qg);
            weights += w;
        }
    }
    vec3 filtered = weights > 0.0 ? sum / weights : centre;
    outRadiance = vec4(uIteration.z == 1 ? filtered * getReflectance(g) : filtered, 1.0);
}
