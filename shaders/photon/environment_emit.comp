// Photon emission from the environment (docs/design.md "Environment"): photon i comes from a
// direction uniform over those the environment shines from (the sphere for a constant, the upper
// hemisphere for the sky) or drawn from an image's pdf, enters the scene's bounding box through
// a point uniform over the box's outline seen along that direction, with the power that
// direction sends through the outline over the photons (radiance x outline area x solid angle /
// photons; for an image radiance / pdf stands for the solid angle), finds its first hit through
// the BVH and makes the first bounce there as a light view's photon does (photon_emit.geom);
// survivors are appended to the bounce buffer. Travel counts from the first hit, as the sun's.
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
// Before bvh.glsl, for its computeHitShadingNormal.
#include "lib/vertex_attributes.glsl"
#include "lib/bvh.glsl"
#include "lib/scene_textures.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "lib/photon_lights.glsl"
#define ENVIRONMENT_LOOKUP_ONLY 1
#include "lib/environment.glsl"

layout(local_size_x = kEnvironmentEmitGroupSize) in;

layout(std430, binding = kBindingBouncePhotons) writeonly buffer BounceBuffer { BouncePhoton bouncePhotons[]; };
layout(std430, binding = kBindingPhotonCounters) buffer CounterBuffer { PhotonCounters counters; };

layout(std140, binding = kBindingPassParams) uniform EnvironmentEmitParamsBlock { EnvironmentEmitParams params; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= params.photons) return;
    uint photon = params.firstPhoton + index;
    uint rng = seedRandom(photon, 0u, params.seed);
    uint generator = params.rngGenerator;
    // The direction the light comes from: uniform in z over [-1, 1] (a sphere) or [0, 1] (the
    // sky's hemisphere), stratified over the photons.
    // An image's: from its pdf, the row's number stratified the same way; 1 / pdf stands for
    // the solid angle.
    bool sky = environment.type.x == kEnvironmentSky;
    float z = (float(index) + nextRandom(rng, generator)) / float(params.photons);
    vec3 toward;
    float solidAngle;
    vec3 radiance;
    if (hasEnvironmentImage()) {
        EnvironmentSample s = sampleEnvironmentImage(vec2(z, nextRandom(rng, generator)));
        if (!(s.pdf > 0.0)) return;
        toward = s.toward;
        solidAngle = 1.0 / s.pdf;
        radiance = s.radiance;
    } else {
        z = sky ? z : 2.0 * z - 1.0;
        float r = sqrt(max(1.0 - z * z, 0.0));
        float phi = kTwoPiF * nextRandom(rng, generator);
        toward = vec3(r * cos(phi), z, r * sin(phi));
        solidAngle = sky ? kTwoPiF : 2.0 * kTwoPiF;
        radiance = evaluateEnvironment(environment, toward);
    }
    if (all(equal(radiance, vec3(0.0)))) return;
    vec3 dir = -toward;
    vec3 u = vec3(nextRandom(rng, generator), nextRandom(rng, generator),
                  nextRandom(rng, generator));
    vec3 entry = sampleBoxEntry(params.sceneMinW, params.sceneExtentM, dir, u);
    // From just outside the box, so that a surface on its face is hit.
    vec3 origin = entry - dir * computeRayOffset(entry, params.rayOffsetM);
    float outline = computeBoxOutlineArea(params.sceneExtentM, dir);
    vec3 power = radiance * (outline * solidAngle / float(params.photons));

    RayHit hit;
    if (!traceRay(origin, dir, kNoHitDistance, hit)) return;
    vec3 position = origin + dir * hit.t;
    vec3 geometric = computeHitNormal(hit);
    bool frontFace = dot(geometric, dir) < 0.0;
    vec3 n = frontFace ? geometric : -geometric;
    vec3 shading = computeHitShadingNormal(hit, n); // the BRDF's; n decides sides
    GpuMaterial m = materials[triangles[hit.triangle].w];
    vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
    vec3 numbers = vec3(nextRandom(rng, generator), nextRandom(rng, generator),
                        nextRandom(rng, generator));
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
    bouncePhotons[slot].positionDistance = vec4(position, 0.0);
    bouncePhotons[slot].directionDensity = vec4(dir, updatePathDensity(1.0, event, m.specular.w));
    bouncePhotons[slot].power = vec4(power, uintBitsToFloat(photon));
    countPhoton(params.light, 0);
}
