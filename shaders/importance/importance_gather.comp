// Importance gather: where do this frame's photons matter? Samples of the viewer's G-buffer (one
// jittered pixel per cell of a coarse grid over the image) add importance to the light-view texels
// that light them: the visible point itself where a light sees it, the point one cosine-sampled
// bounce away (a short ray through the BVH) where a light sees that one, and from a visible point
// that no light sees, the point a second bounce away (importance_pass.cpp). Each hit is splatted
// bilinearly into the light view's coarse map (shared/importance_data.h). A light sees a point as
// the direct pass finds it: by shadow map, or with SHADOW_RAYS 1 by ray.
#ifndef SHADOW_RAYS
#define SHADOW_RAYS 0
#endif
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/lights.glsl"
#include "lib/bvh.glsl"
#include "lib/shadow_rays.glsl"
#include "shared/importance_data.h"
#include "shared/photon_scatter.h"

layout(local_size_x = kImportanceGroupSize) in;

layout(std140, binding = kBindingImportanceParams) uniform ImportanceParamsBlock {
    ImportanceParams params;
};
layout(std430, binding = kBindingImportanceHits) buffer ImportanceHits { uint importanceHits[]; };

#include "lib/viewer_gbuffer.glsl"

// Adds `weight` to the map texels around light-view coordinate `uv` (in [0,1]^2), bilinearly.
void addImportance(uint view, vec2 uv, float weight) {
    vec2 at = uv * float(kImportanceSize) - 0.5;
    ivec2 lo = ivec2(floor(at));
    vec2 f = at - vec2(lo);
    for (int dy = 0; dy <= 1; ++dy) {
        for (int dx = 0; dx <= 1; ++dx) {
            ivec2 t = clamp(lo + ivec2(dx, dy), ivec2(0), ivec2(int(kImportanceSize) - 1));
            float w = (dx == 1 ? f.x : 1.0 - f.x) * (dy == 1 ? f.y : 1.0 - f.y) * weight;
            uint index = view * kImportanceTexels + uint(t.y) * kImportanceSize + uint(t.x);
            atomicAdd(importanceHits[index], uint(w * kImportanceFixedPoint + 0.5));
        }
    }
}

// For every light that sees the surface point (p, n) directly, adds `weight` where its camera
// sees it; whether any does. n may face either way: it is turned towards the light first.
bool addLitPoint(vec3 p, vec3 n, float weight) {
    bool lit = false;
    for (uint i = 0u; i < frame.lightCount; ++i) {
        GpuLight light = lights[i];
        LightSample s = sampleLight(light, p);
        if (all(equal(s.irradiance, vec3(0.0)))) continue;
        vec3 facing = dot(n, s.wi) >= 0.0 ? n : -n;
        uint view = selectLightView(light, p);
        vec4 clip = lightViews[view].clipFromWorld * vec4(p, 1.0);
        if (clip.w <= 0.0) continue;
        vec2 ndc = clip.xy / clip.w;
        if (any(greaterThan(abs(ndc), vec2(1.0)))) continue;
        // The direct pass's shadow maps, also with shadow rays for the lights whose view is drawn
        // to emit photons (a spot's, a point light's: no ray needed to aim them); a sun's fine view
        // is not drawn then and its fitted one is too coarse for a room lit through its door (room
        // relMSE median 0.050 -> 0.073 by that view), so suns take a ray.
#if SHADOW_RAYS
        if (light.views.z == kLightSun) {
            if (computeRayVisibility(p, facing, s, params.rayOffsetM) < 0.5) continue;
        } else
#endif
        if (computeVisibility(light, p, facing) < 0.5) continue;
        addImportance(view, ndc * 0.5 + 0.5, weight);
        lit = true;
    }
    return lit;
}

// A cosine-sampled bounce from the surface point (p, n), n facing the side the ray leaves to: the
// point it hits, with its normal turned to face the ray's origin.
bool traceBounce(vec3 p, vec3 n, inout uint rng, out vec3 q, out vec3 nq) {
    vec3 dir = sampleCosine(n, nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
    vec3 origin = p + n * computeRayOffset(p, params.rayOffsetM);
    RayHit hit;
    if (!traceRay(origin, dir, kNoHitDistance, hit)) return false;
    q = origin + dir * hit.t;
    nq = computeHitNormal(hit);
    nq = dot(nq, dir) < 0.0 ? nq : -nq;
    return true;
}

void main() {
    uint index = gl_GlobalInvocationID.x;
    uvec2 grid = params.gatherSamples;
    if (index >= grid.x * grid.y) return;
    uvec2 cell = uvec2(index % grid.x, index / grid.x);
    uint rng = seedRandom(index, 0u, params.seed);
    vec2 jitter = vec2(nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
    vec2 sizePx = frame.imageSizePx;
    ivec2 pixel = clamp(ivec2((vec2(cell) + jitter) * sizePx / vec2(grid)), ivec2(0), ivec2(sizePx) - 1);
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) return;
    vec3 n = normalize(texelFetch(uNormal, pixel, 0).xyz);
    bool lit = addLitPoint(position.xyz, n, params.visibleWeight);

    // One bounce towards the surfaces that light this one; from an unlit point, a second.
    vec3 q;
    vec3 nq;
    if (!traceBounce(position.xyz, n, rng, q, nq)) return;
    addLitPoint(q, nq, params.bounceWeight);
    if (lit || !traceBounce(q, nq, rng, q, nq)) return;
    addLitPoint(q, nq, params.unlitWeight);
}
