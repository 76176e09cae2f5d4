// Photon tracing: each bounce-buffer photon is traced through the BVH for up to `bounces` more
// hits. Every hit on a surface with a diffuse or glossy part appends a result photon (the light
// that arrives there after k reflections, k = 1..bounces); between hits the photon scatters by
// the same Russian roulette as the first bounce.
#include "lib/scene_buffers.glsl"
// Before bvh.glsl, for its computeHitShadingNormal.
#include "lib/vertex_attributes.glsl"
// Before bvh.glsl, which under BVH_ALPHA_TEST 0 would leave it out (the loader takes a file once).
#include "lib/scene_textures.glsl"
#include "lib/bvh.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "lib/photon_lights.glsl"

layout(local_size_x = kTraceGroupSize) in;

layout(std430, binding = kBindingBouncePhotons) readonly buffer BounceBuffer { BouncePhoton bouncePhotons[]; };
layout(std430, binding = kBindingResultPhotons) writeonly buffer ResultBuffer { ResultPhoton resultPhotons[]; };
layout(std430, binding = kBindingPhotonCounters) buffer CounterBuffer { PhotonCounters counters; };

layout(std140, binding = kBindingPassParams) uniform TraceParamsBlock { TraceParams params; };

// Photons are stored where a splat can show them: diffuse or glossy surfaces; a near-mirror lobe
// is left to further bounces (its reflection would need an image of the mirror, not a splat).
const float kGlossyExponentMax = 1000.0;

bool isStoredSurface(GpuMaterial m) {
    return any(greaterThan(m.diffuse.rgb, vec3(0.0))) ||
           (any(greaterThan(m.specular.rgb, vec3(0.0))) && m.specular.w < kGlossyExponentMax);
}

void storePhoton(vec3 position, float travelled, vec3 normal, float density, vec3 dir,
                 uint reflections, uint light, vec3 power) {
    uint slot = atomicAdd(counters.result.x, 1u);
    if (slot >= counters.result.y) {
        atomicAdd(counters.result.z, 1u); // counted, never written out of bounds
        return;
    }
    resultPhotons[slot].positionDistance = vec4(position, travelled);
    resultPhotons[slot].normalDensity = vec4(normal, density);
    resultPhotons[slot].incoming = vec4(dir, packReflectionsLight(reflections, light));
    countPhoton(light, 1);
    resultPhotons[slot].power = vec4(power, 0.0);
}

uint hashObjectPoint(RayHit hit) {
    const float kGrid = 65536.0; // barycentric steps: a few um on a metre-sized triangle
    uvec2 b = uvec2(hit.barycentric * kGrid);
    return hashPcg(hit.instance ^ hashPcg(hit.triangle ^ hashPcg(b.x ^ hashPcg(b.y))));
}

// Lanes of a work group run in step on a SIMD renderer, and a photon's path ends at any bounce
// (a miss, absorption): so each lane walks its photons one bounce per step and takes its next
// photon (every `lanes`-th of the slice) as soon as one ends, instead of idling until the
// longest path of its group is done (the dispatch's lanes: computeTraceGroups).
void main() {
    uvec2 range = computeSliceRange(counters.bounce.x, params.slice, params.slices);
    uint lanes = gl_NumWorkGroups.x * kTraceGroupSize;
    uint next = range.x + gl_GlobalInvocationID.x;
    uint bounces = params.bounces;
    vec3 position, dir, power;
    float travelled, density;
    uint id, light;
    uint reflections = 0u; // 0: the lane holds no photon
    while (true) {
        if (reflections == 0u) {
            if (next >= range.y) break;
            BouncePhoton photon = bouncePhotons[next];
            next += lanes;
            position = photon.positionDistance.xyz;
            travelled = photon.positionDistance.w;
            dir = photon.directionDensity.xyz;
            density = photon.directionDensity.w;
            power = photon.power.rgb;
            id = floatBitsToUint(photon.power.w);
            light = findPhotonLight(id);
            reflections = 1u;
        }
        float offset = computeRayOffset(position, params.rayOffsetM);
        vec3 origin = position + dir * offset;
        RayHit hit;
        if (!traceRay(origin, dir, kNoHitDistance, hit)) {
            reflections = 0u;
            continue;
        }
        position = origin + dir * hit.t;
        travelled += hit.t + offset;
        vec3 geometric = computeHitNormal(hit);
        bool frontFace = dot(geometric, dir) < 0.0;
        vec3 n = frontFace ? geometric : -geometric;
        // The BRDF's normal, as the G-buffer holds it (stored photons meet that one); n
        // decides sides.
        vec3 shading = computeHitShadingNormal(hit, n);
        GpuMaterial m = materials[triangles[hit.triangle].w];
#if SCENE_NORMAL_MAPS
        // A stored photon's disc lies in the surface's plane, so it takes the normal without the
        // normal map: the map's turn, up to tens of degrees at a brick's bevel, would tilt the
        // flattened disc out of the wall and leave it a strip (docs/design.md "Normal maps").
        // The splats shade with the pixel's own mapped normal.
        vec3 discNormal = computeShadingNormal(hit.triangle, hit.instance, hit.barycentric, n);
#else
        vec3 discNormal = shading;
#endif
        if (isStoredSurface(m)) storePhoton(position, travelled, discNormal, density, dir, reflections, light, power);
        if (reflections == bounces) {
            reflections = 0u;
            continue;
        }
        // object_space: the numbers of where the photon hit, in the hit triangle's own terms
        // (instance, triangle, barycentrics on a 2^-16 grid), so they stay while that surface
        // and the path to it stay, however the object moved; else the photon's emission cell.
        uint key = params.rngMode == kRngObjectSpace ? hashObjectPoint(hit) : id;
        uint rng = seedRandom(key, reflections, params.seed);
        vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
        vec3 wiHit = -dir;
        uint event = scatterPhoton(dir, power, shading, diffuse, m.specular, m.transmissive,
                                   frontFace, rng, params.rngGenerator);
        if (event == kScatterAbsorbed || !isScatterOnGeometricSide(event, dir, n)) {
            reflections = 0u;
            continue;
        }
        if (shading != n) power *= computeShadingAdjoint(wiHit, dir, n, shading);
        density = updatePathDensity(density, event, m.specular.w);
        ++reflections;
    }
}
