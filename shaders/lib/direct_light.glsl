// Direct light at a surface point, one light's or every light's: BRDF x irradiance x cos(theta) x
// visibility, radiance in W/(m^2 sr), as direct.frag shades a viewer pixel, edge_shade.comp a
// sample inside one, and the path tracer (reference.comp) and the specular pass
// (specular_trace.comp) a hit. Visibility from the light views' shadow maps, or with
// SHADOW_RAYS 1 (setting shadows ray; the tracers always) from a ray to the light through the
// BVH. Needs brdf.glsl and lights.glsl included before, and with SHADOW_RAYS 1 bvh.glsl.
#ifndef SHADOW_RAYS
#define SHADOW_RAYS 0
#endif
#if SHADOW_RAYS
#include "shadow_rays.glsl"
#endif

// `n` (the geometric normal) faces the viewer and decides whether the light is above the
// surface and where a shadow ray leaves; `shading` (the shading normal, on n's side) gives the
// BRDF and its cosine. `wo` points to the viewer; rayFloorM: the shadow ray's offset floor
// (GpuScene::getRayEpsilon; unused with shadow maps).
vec3 computeShadedLightRadiance(GpuLight light, vec3 position, vec3 n, vec3 shading,
                                vec3 diffuse, vec4 specular, vec3 wo, float rayFloorM) {
    LightSample s = sampleLight(light, position);
    float cosTheta = dot(shading, s.wi);
    if (dot(n, s.wi) <= 0.0 || cosTheta <= 0.0 || all(equal(s.irradiance, vec3(0.0)))) {
        return vec3(0.0);
    }
#if SHADOW_RAYS
    float visibility = computeRayVisibility(position, n, s, rayFloorM);
#else
    float visibility = computeVisibility(light, position, n);
#endif
    return evaluateBrdf(diffuse, specular, shading, s.wi, wo) * s.irradiance * cosTheta *
           visibility;
}

// A flat-shaded surface: the geometric normal shades.
vec3 computeLightRadiance(GpuLight light, vec3 position, vec3 n, vec3 diffuse, vec4 specular,
                          vec3 wo, float rayFloorM) {
    return computeShadedLightRadiance(light, position, n, n, diffuse, specular, wo, rayFloorM);
}

// Every light of the scene (frame.lightCount).
vec3 computeShadedDirectRadiance(vec3 position, vec3 n, vec3 shading, vec3 diffuse,
                                 vec4 specular, vec3 wo, float rayFloorM) {
    vec3 radiance = vec3(0.0);
    for (uint i = 0u; i < frame.lightCount; ++i) {
        radiance += computeShadedLightRadiance(lights[i], position, n, shading, diffuse, specular,
                                               wo, rayFloorM);
    }
    return radiance;
}

vec3 computeDirectRadiance(vec3 position, vec3 n, vec3 diffuse, vec4 specular, vec3 wo,
                           float rayFloorM) {
    return computeShadedDirectRadiance(position, n, n, diffuse, specular, wo, rayFloorM);
}
