// Joint-bilateral upsample of the indirect light (UpsamplePass): the buffer pixel i stands for
// the viewer G-buffer pixel i d + d / 2 (splat.frag), so an image pixel lies between four of
// them. Each of the 4x4 nearest is weighted by a tent over two buffer pixels, by the normal test
// and the off-plane distance of the filter (atrous.frag), and read as irradiance (the filter's
// output is; the splats as they are are divided by the reflectance at their own G-buffer pixel);
// the sum is multiplied by the pixel's reflectance. A
// pixel no buffer pixel shares a surface with (a feature thinner than d pixels) takes the tent
// alone. At a buffer of the image's size the light passes as it is. The caustic photons'
// light, splatted apart at the image's size and unfiltered (shared/photon_data.h,
// kSplatCausticPhotons), is added when iteration.x is 1.
#include "lib/frame_constants.glsl"
#include "lib/gbuffer_filter.glsl"

layout(binding = kUnitFilterSource) uniform sampler2D uSource;
layout(binding = kUnitCaustics) uniform sampler2D uCaustics;

layout(std140, binding = kBindingPassParams) uniform FilterParamsBlock { FilterParams params; };

layout(location = 0) out vec4 outRadiance;

const float kMinWeight = 1e-4; // below: no buffer pixel shares the surface

vec3 upsample(ivec2 pixel);

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 caustics = params.iteration.x == 1 ? texelFetch(uCaustics, pixel, 0).rgb : vec3(0.0);
    outRadiance = vec4(upsample(pixel) + caustics, 1.0);
}

vec3 upsample(ivec2 pixel) {
    if (params.iteration.w == 1) return texelFetch(uSource, pixel, 0).rgb;
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) return vec3(0.0);
    ivec2 size = textureSize(uSource, 0);
    vec3 n = texelFetch(uNormal, pixel, 0).xyz;
    // Footprints of a buffer pixel on this surface.
    float planeScale = computePlaneScale(pixel, position.xyz, params.iteration.w);
    vec2 at = (vec2(pixel) - float(params.iteration.w / 2)) / float(params.iteration.w); // in buffer pixels
    ivec2 first = ivec2(floor(at)) - 1;
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    vec3 tentSum = vec3(0.0);
    float tentWeights = 0.0;
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            ivec2 q = first + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec2 offset = abs(vec2(q) - at);
            float tent = max(1.0 - 0.5 * offset.x, 0.0) * max(1.0 - 0.5 * offset.y, 0.0);
            ivec2 qg = getBlockGBufferPixel(q, params.iteration.w);
            vec4 qPosition = texelFetch(uPosition, qg, 0);
            if (tent <= 0.0 || qPosition.w < 0.5) continue;
            vec3 irradiance = texelFetch(uSource, q, 0).rgb;
            if (params.iteration.y == 1) irradiance /= getReflectance(qg);
            float w = tent * weighTapAt(qg, qPosition, n, position.xyz, planeScale);
            sum += w * irradiance;
            weights += w;
            tentSum += tent * irradiance;
            tentWeights += tent;
        }
    }
    vec3 irradiance = weights > kMinWeight ? sum / weights
                                            : (tentWeights > 0.0 ? tentSum / tentWeights : vec3(0.0));
    return irradiance * getReflectance(pixel);
}
