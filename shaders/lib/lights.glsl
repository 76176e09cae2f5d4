// Light evaluation: incident direction, distance and irradiance (W/m^2 on a surface facing the
// light) of point, spot and sun lights, and shadow-map visibility from the light G-buffers.
// Needs scene_buffers.glsl and frame_constants.glsl included before.

// LIGHT_TYPES: the light types (bits 1 << kLight*) the includer's lights can have, all by
// default. DirectPass draws with the types of each draw's lights, so the code of the others is
// compiled out: llvmpipe runs every branch, the sun's pixels paid for a point light's cube face
// and a spot's falloff.
#ifndef LIGHT_TYPES
#define LIGHT_TYPES 7u
#endif
const bool kHasPointLights = (LIGHT_TYPES & (1u << kLightPoint)) != 0u;
const bool kHasSpotLights = (LIGHT_TYPES & (1u << kLightSpot)) != 0u;
const bool kHasSunLights = (LIGHT_TYPES & (1u << kLightSun)) != 0u;
const bool kHasOnlySuns = !kHasPointLights && !kHasSpotLights;

struct LightSample {
    vec3 wi;          // unit direction toward the light
    float distanceM;  // to the light (huge for the sun)
    vec3 irradiance;  // on a surface facing the light, falloff included
};

LightSample sampleLight(GpuLight light, vec3 positionW) {
    LightSample s;
    uint type = light.views.z;
    if (kHasOnlySuns || (kHasSunLights && type == kLightSun)) {
        s.wi = -light.directionCos.xyz;
        s.distanceM = 1e30;
        s.irradiance = light.power.rgb;
        return s;
    }
    vec3 toLight = light.position.xyz - positionW;
    float d2 = max(dot(toLight, toLight), 1e-30); // a point on the light: finite, not 1/0
    s.distanceM = sqrt(d2);
    s.wi = toLight / s.distanceM;
    float falloff = 1.0;
    if (kHasSpotLights && type == kLightSpot) {
        falloff = computeSpotFalloffCos(dot(-s.wi, light.directionCos.xyz), light.power.w,
                                     light.directionCos.w);
    }
    s.irradiance = light.power.rgb * (falloff / d2);
    return s;
}

// Which light view (G-buffer layer) sees `positionW`: a point light picks the cube face of the
// direction's major axis, in the order +x, -x, +y, -y, +z, -z.
uint selectLightView(GpuLight light, vec3 positionW) {
    uint first = light.views.x;
    if (!kHasPointLights || light.views.y < 6u) return first;
    vec3 d = positionW - light.position.xyz;
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return first + (d.x >= 0.0 ? 0u : 1u);
    if (a.y >= a.z) return first + (d.y >= 0.0 ? 2u : 3u);
    return first + (d.z >= 0.0 ? 4u : 5u);
}

#include "light_gbuffer.glsl"

// 1 if nothing in the light's G-buffer lies between the light and the point, else 0. The point
// is pushed off its surface along the normal and compared with a depth bias, both measured in
// light-camera texels at the point's depth, so the bias scales with the shadow map's resolution.
// The view whose shadow map holds `positionW`: the sun's fitted view (finer, around what the
// viewer sees) where the point lies inside it, a few texels from its border, else
// selectLightView's.
uint selectShadowView(GpuLight light, vec3 positionW) {
    if (kHasSunLights && light.views.w != 0u) {
        uint fine = light.views.w - 1u;
        vec4 clip = lightViews[fine].clipFromWorld * vec4(positionW, 1.0);
        float inside = 1.0 - 4.0 / frame.lightResolutionPx; // the normal offset and jitter stay inside
        if (all(lessThan(abs(clip.xy / clip.w), vec2(inside)))) return fine;
    }
    return selectLightView(light, positionW);
}

float computeVisibility(GpuLight light, vec3 positionW, vec3 normalW) {
    uint viewIndex = selectShadowView(light, positionW);
    GpuLightView view = lightViews[viewIndex];
    vec3 axis = view.axisTexel.xyz;
    // Only suns look through orthographic views.
    bool ortho = kHasOnlySuns || (kHasSunLights && view.info.y == 1u);
    float depth = dot(positionW - view.originAxis.xyz, axis);
    float texelM = ortho ? view.axisTexel.w : view.axisTexel.w * max(depth, 0.0);
    float biasM = frame.shadowBiasTexels * texelM;
    // The normal offset grows with the angle to the light (sin): a surface facing the light
    // needs none, one at grazing light the whole bias; it moves shadow edges by as much.
    vec3 toLight = ortho ? -axis : normalize(view.originAxis.xyz - positionW);
    float cosLight = clamp(abs(dot(normalW, toLight)), 0.0, 1.0);
    vec3 p = positionW + normalW * (biasM * sqrt(1.0 - cosLight * cosLight));
    vec4 clip = view.clipFromWorld * vec4(p, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    if (any(greaterThan(abs(ndc.xy), vec2(1.0)))) return 1.0; // outside: the falloff decides
    int resolution = int(frame.lightResolutionPx);
    ivec2 texel = clamp(ivec2((ndc.xy * 0.5 + 0.5) * float(resolution)), ivec2(0), ivec2(resolution - 1));
    vec4 occluder = texelFetch(uLightPosition, ivec3(texel, int(viewIndex)), 0);
    if (occluder.w < 0.5) return 1.0; // the light sees nothing there
    float occluderDepth = dot(occluder.xyz - view.originAxis.xyz, axis);
    float receiverDepth = dot(p - view.originAxis.xyz, axis);
    return receiverDepth <= occluderDepth + biasM ? 1.0 : 0.0;
}
