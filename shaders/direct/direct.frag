// Direct light, deferred: for every viewer G-buffer pixel, the sum over lights of
// BRDF * irradiance * cos(theta) * visibility (lib/direct_light.glsl), radiance in W/(m^2 sr), at
// the pixel's centre (edge_find.comp and edge_shade.comp then average it over the area of the
// pixels where it changes). Each draw shades the lights its parameter block lists (DirectPass:
// the lights that reach every direction over the whole image, a spot light over the pixels its
// cone can light), and adds to the draws before. Visibility from the light views' shadow maps,
// or with SHADOW_RAYS 1 (setting shadows ray) from a ray to the light through the BVH; the
// emitting triangles' light (EMITTERS 1) by rays always.
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/brdf.glsl"
#include "lib/lights.glsl"
#ifndef SHADOW_RAYS
#define SHADOW_RAYS 0
#endif
// EMITTERS 1: the scene has emitting triangles or an environment (DirectPass), shaded in the
// first draw from area_samples points on them and area_samples directions to the sky per pixel,
// each with a shadow ray (lib/emitters.glsl, lib/environment.glsl).
#ifndef EMITTERS
#define EMITTERS 0
#endif
#if SHADOW_RAYS || EMITTERS
#include "lib/bvh.glsl"
#endif
#include "lib/direct_light.glsl"
#if EMITTERS
#include "lib/emitters.glsl"
#include "lib/environment.glsl"
#endif

#include "lib/viewer_gbuffer.glsl"

layout(std140, binding = kBindingPassParams) uniform DirectParamsBlock { DirectParams params; };

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) {
        outRadiance = vec4(0.0); // alpha: no surface covers the pixel (compose.frag); adds 0
        return;
    }
    vec3 n = texelFetch(uNormal, pixel, 0).xyz;
    vec3 diffuse = texelFetch(uDiffuse, pixel, 0).rgb;
    vec4 specular = texelFetch(uSpecular, pixel, 0);
    vec3 wo = normalize(frame.cameraPosW - position.xyz);
    vec3 radiance = vec3(0.0);
    float rayFloorM = params.rayFloorM;
    for (uint k = 0u; k < params.lightCount; ++k) {
        GpuLight light = lights[params.lights[k / 4u][k % 4u]];
        radiance += computeLightRadiance(light, position.xyz, n, diffuse, specular, wo, rayFloorM);
    }
#if EMITTERS
    if (params.firstDraw == 1u) {
        uint key = uint(pixel.y) * uint(frame.imageSizePx.x) + uint(pixel.x);
        radiance += computeEmitterRadiance(position.xyz, n, n, diffuse, specular, wo, rayFloorM, 0u,
                                           frame.areaSamples,
                                           computeEmitterSeeds(key, kEmitterSeedSlot));
        radiance += computeEnvironmentRadiance(position.xyz, n, n, diffuse, specular, wo, rayFloorM,
                                               0u, frame.areaSamples,
                                               computeEmitterSeeds(key, kEnvironmentSeedSlot));
    }
#endif
    // Coverage once: the draws after the first add their light and 0.
    outRadiance = vec4(radiance, params.firstDraw == 1u ? 1.0 : 0.0);
}
