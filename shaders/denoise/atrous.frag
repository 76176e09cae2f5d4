// One iteration of the edge-aware a-trous filter on the indirect light (Dammertz et al. 2010):
// a 5x5 B3-spline kernel with holes of `step` pixels, each tap weighted down where the surface
// turns (normals) or steps away from the pixel's plane (positions, in pixel footprints). It
// filters irradiance (filter_input.frag divided the splats by the reflectance) and reads the
// taps' surfaces from the guide; the last iteration multiplies by the reflectance again, unless
// an upsample to the image's resolution follows, which reads irradiance.
#include "lib/frame_constants.glsl"
#include "lib/gbuffer_filter.glsl"

layout(binding = kUnitFilterSource) uniform sampler2D uSource;
layout(binding = kUnitFilterGuide) uniform sampler2D uGuide;

layout(std140, binding = kBindingPassParams) uniform FilterParamsBlock { FilterParams params; };

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 g = getBlockGBufferPixel(pixel, params.iteration.w);
    vec4 guide = texelFetch(uGuide, pixel, 0);
    vec3 centre = texelFetch(uSource, pixel, 0).rgb;
    vec3 filtered = centre;
    if (guide.w != kGuideNoSurface) {
        ivec2 size = textureSize(uSource, 0);
        vec3 n = decodeGuideNormal(guide.w);
        // Footprints of a filtered pixel on its surface, times the step.
        float planeScale =
            computePlaneScale(g, guide.xyz, params.iteration.w) / float(params.iteration.x);
        const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
        vec3 sum = vec3(0.0);
        float weights = 0.0;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                ivec2 q = pixel + ivec2(dx, dy) * params.iteration.x;
                if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
                float w = kB3[abs(dx)] * kB3[abs(dy)] *
                          weighGuide(texelFetch(uGuide, q, 0), n, guide.xyz, planeScale);
                if (w <= 0.0) continue;
                sum += w * texelFetch(uSource, q, 0).rgb;
                weights += w;
            }
        }
        if (weights > 0.0) filtered = sum / weights;
    }
    outRadiance = vec4(params.iteration.y == 1 ? filtered * getReflectance(g) : filtered, 1.0);
}
