// One iteration of the edge-aware a-trous filter on the indirect light (Dammertz et al. 2010):
// a 5x5 B3-spline kernel with holes of `step` pixels, each tap weighted down where the surface
// turns (normals) or steps away from the pixel's plane (positions, in pixel footprints). The
// first iteration divides the light by the diffuse reflectance, so the filter smooths irradiance
// and keeps texture and colour edges; the last multiplies it back, unless an upsample to the
// image's resolution follows, which reads irradiance.
#include "lib/frame_constants.glsl"
#include "lib/gbuffer_filter.glsl"

layout(binding = kUnitFilterSource) uniform sampler2D uSource;

layout(std140, binding = kBindingPassParams) uniform FilterParamsBlock { FilterParams params; };

layout(location = 0) out vec4 outRadiance;

vec3 readSource(ivec2 pixel, ivec2 g) {
    vec3 c = texelFetch(uSource, pixel, 0).rgb;
    return params.iteration.y == 1 ? c / getReflectance(g) : c;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 g = getBlockGBufferPixel(pixel, params.iteration.w);
    vec4 position = texelFetch(uPosition, g, 0);
    vec3 centre = readSource(pixel, g);
    if (position.w < 0.5) {
        outRadiance = vec4(centre, 1.0);
        return;
    }
    ivec2 size = textureSize(uSource, 0);
    vec3 n = texelFetch(uNormal, g, 0).xyz;
    // Footprints of a filtered pixel on its surface, times the step.
    float planeScale = computePlaneScale(g, position.xyz, params.iteration.w) / float(params.iteration.x);
    const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = pixel + ivec2(dx, dy) * params.iteration.x;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            ivec2 qg = getBlockGBufferPixel(q, params.iteration.w);
            float w = kB3[abs(dx)] * kB3[abs(dy)] * weighTap(qg, n, position.xyz, planeScale);
            if (w <= 0.0) continue;
            sum += w * readSource(q, qg);
            weights += w;
        }
    }
    vec3 filtered = weights > 0.0 ? sum / weights : centre;
    outRadiance = vec4(params.iteration.z == 1 ? filtered * getReflectance(g) : filtered, 1.0);
}
