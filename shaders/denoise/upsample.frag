// Joint-bilateral upsample of the indirect light (UpsamplePass): the buffer pixel i stands for
// the viewer G-buffer pixel i d + d / 2 (splat.frag), so an image pixel lies between four of
// them. Each of the four is weighted bilinearly, by the normal test and the off-plane distance
// of the filter (atrous.comp) on its guide texel (filter_input.frag), and read as irradiance;
// the sum is multiplied by the pixel's reflectance. A tap counts only on the pixel's own
// surface: a surface weight of kSharedSurface or more (the footprint measured towards the nearest
// of the pixel's four neighbours d pixels away, computePlaneScale), and its point within
// kSameSurfaceReach footprints (not another surface in the same plane: the room's floor beyond
// the door, the yard before it).
// A pixel none of the four shares a surface with (a feature thinner than d pixels) takes the
// bilinear weights alone. At a buffer of the image's size the light passes as it is. The caustic
// photons' light, splatted apart at the image's size and unfiltered (shared/photon_data.h,
// kSplatCausticPhotons), is added by the UPSAMPLE_CAUSTICS 1 variant. UPSAMPLE_FILTER 0: the
// buffer is the image's size (only the caustic light to add). Variants, not uniforms: llvmpipe
// runs both sides of every branch.
#include "lib/frame_constants.glsl"
#include "lib/gbuffer_filter.glsl"

layout(binding = kUnitFilterSource) uniform sampler2D uSource;
layout(binding = kUnitCaustics) uniform sampler2D uCaustics;
layout(binding = kUnitFilterGuide) uniform sampler2D uGuide;

layout(std140, binding = kBindingPassParams) uniform FilterParamsBlock { FilterParams params; };

layout(location = 0) out vec4 outRadiance;

const float kMinWeight = 1e-6; // below: no buffer pixel shares the surface
const float kTentFloor = 1e-2;
// A tap's surface weight below this: another surface (e^-3 of the plane test, three footprints
// off the pixel's plane, or normals 17 degrees apart under the normal test's cos^64).
const float kSharedSurface = 0.05;
// A tap's point farther than this many footprints along the plane: another surface in the same
// plane. The four taps lie within 1.5 buffer pixels of the pixel on screen, so a continuous
// surface holds them within about 2 footprints; a surface seen at under about 20 degrees, whose
// footprint along the view is 2.7 or more times its nearest, loses its far taps and may take the
// bilinear weights alone (the distant yard near the horizon, among its own light).
const float kSameSurfaceReach = 4.0;

vec3 upsample(ivec2 pixel);

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
#if UPSAMPLE_CAUSTICS
    vec3 caustics = texelFetch(uCaustics, pixel, 0).rgb;
#else
    vec3 caustics = vec3(0.0);
#endif
    outRadiance = vec4(upsample(pixel) + caustics, 1.0);
}

vec3 upsample(ivec2 pixel) {
#if !UPSAMPLE_FILTER
    return texelFetch(uSource, pixel, 0).rgb;
#else
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) return vec3(0.0);
    ivec2 size = textureSize(uSource, 0);
    vec3 n = texelFetch(uNormal, pixel, 0).xyz;
    // Footprints of a buffer pixel on this surface.
    float planeScale = computePlaneScale(pixel, position.xyz, params.pixelsPerBufferPx);
    vec2 at = (vec2(pixel) - float(params.pixelsPerBufferPx / 2)) / float(params.pixelsPerBufferPx); // in buffer pixels
    ivec2 first = ivec2(floor(at));
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    vec3 tentSum = vec3(0.0);
    float tentWeights = 0.0;
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 2; ++x) {
            ivec2 q = first + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec2 offset = abs(vec2(q) - at);
            // Bilinear, with a floor that lets a tap on the pixel's own surface count where
            // the nearer ones lie on another.
            float tent = max(1.0 - offset.x, kTentFloor) * max(1.0 - offset.y, kTentFloor);
            vec4 guide = texelFetch(uGuide, q, 0);
            if (guide.w == kGuideNoSurface) continue;
            vec3 irradiance = texelFetch(uSource, q, 0).rgb;
            float shared_ = weighGuide(guide, n, position.xyz, planeScale);
            // planeScale is 1 / (kPlaneFootprints footprints).
            float footprints = length(guide.xyz - position.xyz) * planeScale * kPlaneFootprints;
            bool near = footprints <= kSameSurfaceReach;
            float w = shared_ >= kSharedSurface && near ? tent * shared_ : 0.0;
            sum += w * irradiance;
            weights += w;
            tentSum += tent * irradiance;
            tentWeights += tent;
        }
    }
    vec3 irradiance = weights > kMinWeight ? sum / weights
                                            : (tentWeights > 0.0 ? tentSum / tentWeights : vec3(0.0));
    return irradiance * getReflectance(pixel);
#endif
}
