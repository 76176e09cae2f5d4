// Photon emission from emitting triangles (docs/design.md "Emitters"): photon i of a group picks
// a triangle by power (stratified over the group's power), a uniform point on it and a
// cosine-weighted direction on its emitting side (either side of a two-sided emitter, each with
// probability 1/2), finds its first hit through the BVH, and there makes the first bounce by the
// same Russian roulette as a light view's photon (photon_emit.geom); survivors are appended to
// the bounce buffer after the light views' photons. Each carries the group's power / photons,
// in the colour of its emitter.
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
// Before bvh.glsl, for its computeHitShadingNormal.
#include "lib/vertex_attributes.glsl"
#include "lib/bvh.glsl"
#include "lib/scene_textures.glsl"
#include "shared/emitter_data.h"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "lib/photon_lights.glsl"

layout(local_size_x = kEmitterEmitGroupSize) in;

layout(std430, binding = kBindingBouncePhotons) writeonly buffer BounceBuffer { BouncePhoton bouncePhotons[]; };
layout(std430, binding = kBindingPhotonCounters) buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingEmitters) readonly buffer SceneEmitters { GpuEmitter emitters[]; };

layout(std140, binding = kBindingPassParams) uniform EmitterEmitParamsBlock { EmitterEmitParams params; };

// The group's row whose cumulative pick probability first exceeds u (in the table's terms).
uint findGroupEmitter(float u) {
    uint lo = params.firstEmitter;
    uint hi = params.firstEmitter + params.emitterCount - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (emitters[mid].p0Cdf.w <= u) lo = mid + 1u;
        else hi = mid;
    }
    return lo;
}

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= params.photons) return;
    uint photon = params.firstPhoton + index;
    uint rng = seedRandom(photon, 0u, params.seed);
    uint generator = params.rngGenerator;
    // The group's span of the table's cumulative probabilities.
    float cdfLo = params.firstEmitter == 0u ? 0.0 : emitters[params.firstEmitter - 1u].p0Cdf.w;
    float cdfHi = emitters[params.firstEmitter + params.emitterCount - 1u].p0Cdf.w;
    float pick = (float(index) + nextRandom(rng, generator)) / float(params.photons);
    GpuEmitter e = emitters[findGroupEmitter(mix(cdfLo, cdfHi, pick))];
    float r = sqrt(nextRandom(rng, generator));
    float v = nextRandom(rng, generator);
    vec3 point = e.p0Cdf.xyz + e.edge1Area.xyz * (r * (1.0 - v)) + e.edge2Group.xyz * (r * v);
    vec3 normal = normalize(cross(e.edge1Area.xyz, e.edge2Group.xyz));
    if (e.radiance.w > 0.5 && nextRandom(rng, generator) < 0.5) normal = -normal;
    vec3 dir = sampleCosine(normal, nextRandom(rng, generator), nextRandom(rng, generator));
    // Power = radiance x pi x area x sides / (the triangle's share of the group x photons) =
    // radiance / mean(radiance) x group power / photons.
    float meanRadiance = computeMean(e.radiance.rgb);
    if (!(meanRadiance > 0.0)) return;
    vec3 power = e.radiance.rgb * (params.groupWeight / (meanRadiance * float(params.photons)));

    float offset = computeRayOffset(point, params.rayOffsetM);
    vec3 origin = point + normal * offset;
    RayHit hit;
    if (!traceRay(origin, dir, kNoHitDistance, hit)) return;
    vec3 position = origin + dir * hit.t;
    float travelled = hit.t + offset;
    vec3 geometric = computeHitNormal(hit);
    bool frontFace = dot(geometric, dir) < 0.0;
    vec3 n = frontFace ? geometric : -geometric;
    vec3 shading = computeHitShadingNormal(hit, n); // the BRDF's; n decides sides
    GpuMaterial m = materials[triangles[hit.triangle].w];
    vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
    vec3 numbers = vec3(nextRandom(rng, generator), nextRandom(rng, generator),
                        nextRandom(rng, generator));
    // first_bounce weighted: the lobes' probabilities scaled to sum to 1, as photon_emit.geom.
    float albedo = computeLobeAlbedo(diffuse, m.specular, m.transmissive);
    if (!(albedo > 0.0)) return;
    float selectScale = params.firstBounce == kFirstBounceWeighted ? 1.0 / albedo : 1.0;
    vec3 wiHit = -dir;
    uint event = scatterSurfaceWith(dir, power, shading, diffuse, m.specular, m.transmissive,
                                    frontFace, numbers, selectScale);
    if (event == kScatterAbsorbed || !isScatterOnGeometricSide(event, dir, n)) return;
    if (shading != n) power *= computeShadingAdjoint(wiHit, dir, n, shading);
    uint slot = atomicAdd(counters.bounce.x, 1u);
    if (slot >= params.bounceCapacity) return; // photon_prepare.comp clamps the count
    bouncePhotons[slot].positionDistance = vec4(position, travelled);
    bouncePhotons[slot].directionDensity = vec4(dir, updatePathDensity(1.0, event, m.specular.w));
    bouncePhotons[slot].power = vec4(power, uintBitsToFloat(photon));
    countPhoton(params.light, 0);
}
