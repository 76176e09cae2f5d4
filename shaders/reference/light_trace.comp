// Reference light tracer (reference_method = light): one path per invocation leaves a light or a
// point on the emitting triangles (chosen in proportion to their power) and scatters by the photons' own roulette; every vertex on
// a diffuse or glossy surface is connected to the pinhole camera with a shadow ray and its
// measured radiance added to the pixel it projects into. Delta lights seen through glass or in
// mirrors (caustics) converge here, which camera paths with next-event estimation cannot do.
// `bounces` B as everywhere: vertex k carries light reflected k - 1 times, kept for k <= B + 1.
#include "lib/scene_buffers.glsl"
// Before bvh.glsl, for its computeHitShadingNormal (normal maps read the textures).
#include "lib/vertex_attributes.glsl"
#include "lib/scene_textures.glsl"
#include "lib/frame_constants.glsl"
#include "lib/bvh.glsl"
#include "lib/brdf.glsl"
#include "lib/emitters.glsl"
#include "shared/photon_scatter.h"
#include "shared/light_trace_data.h"

layout(local_size_x = 64) in;

layout(std140, binding = kBindingPassParams) uniform LightTraceParamsBlock { LightTraceParams params; };
layout(std430, binding = kBindingLightSplat) buffer LightSplat { uint splat[]; };

// A compare-and-swap loop never needs this many tries (one invocation wins each round); the
// bound only keeps a broken driver from hanging.
const uint kMaxSwapTries = 65536u;

void addToSplat(uint index, float value) {
    uint expected = splat[index];
    for (uint i = 0u; i < kMaxSwapTries; ++i) {
        uint desired = floatBitsToUint(uintBitsToFloat(expected) + value);
        uint previous = atomicCompSwap(splat[index], expected, desired);
        if (previous == expected) return;
        expected = previous;
    }
}

// Power the light sends into the scene (W, mean over rgb): the weight of its share of paths.
float computeLightPowerW(GpuLight light) {
    float mean = computeMean(light.power.rgb);
    uint type = light.views.z;
    if (type == kLightSun) return mean * kPi * params.sceneRadiusM * params.sceneRadiusM;
    if (type == kLightSpot) return mean * kTwoPiF * (1.0 - light.directionCos.w);
    return mean * 2.0 * kTwoPiF;
}

// A ray leaving a light: origin, unit direction and power (W) divided by the probability of
// choosing it. False when the scene has no light with power.
bool sampleLightRay(inout uint rng, out vec3 origin, out vec3 dir, out vec3 powerW) {
    float total = 0.0;
    for (uint i = 0u; i < frame.lightCount; ++i) total += computeLightPowerW(lights[i]);
    // The emitting triangles together, by the power they send out (mean over rgb).
    float emitterPower = frame.emitterCount > 0u ? frame.emitterWeight : 0.0;
    total += emitterPower;
    if (total <= 0.0) return false;
    float u = nextRandom(rng, kRngPcg) * total;
    if (u < emitterPower) {
        // A triangle by power, a uniform point, a side, a cosine-weighted direction: each path
        // carries the emitters' power over the paths, in its triangle's colour.
        GpuEmitter e = emitters[findEmitter(u / emitterPower)];
        float r = sqrt(nextRandom(rng, kRngPcg));
        float v = nextRandom(rng, kRngPcg);
        vec3 point = e.p0Cdf.xyz + e.edge1Area.xyz * (r * (1.0 - v)) + e.edge2Group.xyz * (r * v);
        vec3 normal = normalize(cross(e.edge1Area.xyz, e.edge2Group.xyz));
        if (e.radiance.w > 0.5 && nextRandom(rng, kRngPcg) < 0.5) normal = -normal;
        dir = sampleCosine(normal, nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
        origin = point + normal * computeRayOffset(point, params.rayFloorM);
        float choice = emitterPower / total;
        powerW = e.radiance.rgb * (emitterPower / (computeMean(e.radiance.rgb) * choice));
        return true;
    }
    u -= emitterPower;
    uint chosen = frame.lightCount - 1u;
    for (uint i = 0u; i < frame.lightCount; ++i) {
        float w = computeLightPowerW(lights[i]);
        if (u < w) { chosen = i; break; }
        u -= w;
    }
    GpuLight light = lights[chosen];
    float choice = computeLightPowerW(light) / total;
    if (choice <= 0.0) return false;
    float u1 = nextRandom(rng, kRngPcg);
    float u2 = nextRandom(rng, kRngPcg);
    vec3 t;
    vec3 b;
    uint type = light.views.z;
    if (type == kLightSun) {
        // Uniform over a disc facing the sun, outside the scene's bounding sphere: each path
        // carries E x (disc area) / paths.
        dir = light.directionCos.xyz;
        buildBasis(dir, t, b);
        float radius = params.sceneRadiusM;
        float r = radius * sqrt(u1);
        float phi = kTwoPiF * u2;
        origin = params.sceneCentreW - dir * (2.0 * radius) + t * (r * cos(phi)) +
                 b * (r * sin(phi));
        powerW = light.power.rgb * (kPi * radius * radius / choice);
        return true;
    }
    origin = light.position.xyz;
    if (type == kLightSpot) {
        // Uniform in the outer cone's solid angle 2 pi (1 - cos outer), weighted by the falloff.
        float cosOuter = light.directionCos.w;
        float cosTheta = 1.0 - u1 * (1.0 - cosOuter);
        float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
        float phi = kTwoPiF * u2;
        buildBasis(light.directionCos.xyz, t, b);
        dir = normalize(t * (sinTheta * cos(phi)) + b * (sinTheta * sin(phi)) +
                        light.directionCos.xyz * cosTheta);
        float falloff = computeSpotFalloffCos(cosTheta, light.power.w, cosOuter);
        powerW = light.power.rgb * (falloff * kTwoPiF * (1.0 - cosOuter) / choice);
        return true;
    }
    // Point light: uniform over the sphere, 4 pi sr.
    float z = 1.0 - 2.0 * u1;
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = kTwoPiF * u2;
    dir = vec3(r * cos(phi), r * sin(phi), z);
    powerW = light.power.rgb * (2.0 * kTwoPiF / choice);
    return true;
}

// Adds the radiance this vertex sends to the eye, W/(m^2 sr) averaged over the pixel it lands
// in: power x BRDF x cos(surface) / (d^2 x pixel area on the image plane x cos^3(camera)) (the
// pinhole's importance for a box-filtered pixel), over this sample's path count.
// n: the geometric normal on the side the light came from; shading: the BRDF's, on n's side.
void connectToCamera(vec3 position, vec3 n, vec3 shading, vec3 wiLight, GpuMaterial m,
                     vec3 powerW) {
    vec3 toEye = frame.cameraPosW - position;
    float d2 = dot(toEye, toEye);
    float d = sqrt(d2);
    vec3 wo = toEye / d;
    float cosSurface = dot(n, wo);
    float cosCamera = -dot(wo, params.cameraAxisW);
    if (cosSurface <= 0.0 || cosCamera <= 0.0) return;
    ivec2 pixel;
    if (!findViewerPixel(position, pixel)) return;
    vec3 f = evaluateBrdf(m.diffuse.rgb, m.specular, shading, wiLight, wo);
    if (all(equal(f, vec3(0.0)))) return;
    // The flux arrived over the geometric area; the camera path gathers it with the shading
    // cosine (computeShadingAdjoint with wo's cosine left in `importance`).
    if (shading != n) f *= abs(dot(wiLight, shading)) / abs(dot(wiLight, n));
    float offset = computeRayOffset(position, params.rayFloorM);
    if (isRayBlocked(position + n * offset, wo, d - offset)) return;
    float importance = cosSurface /
        (d2 * params.pixelAreaM2 * cosCamera * cosCamera * cosCamera * float(params.pathCount));
    vec3 value = powerW * f * importance;
    uint index = 3u * uint(pixel.y * int(frame.imageSizePx.x) + pixel.x);
    addToSplat(index, value.r);
    addToSplat(index + 1u, value.g);
    addToSplat(index + 2u, value.b);
}

void main() {
    uint path = gl_GlobalInvocationID.x;
    if (path >= params.pathCount) return;
    uint rng = seedRandom(path, params.sampleIndex, params.seed);
    vec3 origin;
    vec3 dir;
    vec3 powerW;
    if (!sampleLightRay(rng, origin, dir, powerW)) return;
    if (all(equal(powerW, vec3(0.0)))) return;
    uint bounces = params.bounces;
    for (uint vertex = 1u; vertex <= bounces + 1u; ++vertex) {
        RayHit hit;
        if (!traceRay(origin, dir, kNoHitDistance, hit)) break;
        vec3 position = origin + dir * hit.t;
        vec3 geometric = computeHitNormal(hit);
        bool frontFace = dot(geometric, dir) < 0.0;
        vec3 n = frontFace ? geometric : -geometric;
        vec3 shading = computeHitShadingNormal(hit, n); // the BRDF's; n decides sides
        GpuMaterial m = materials[triangles[hit.triangle].w];
        if (any(greaterThan(m.diffuse.rgb + m.specular.rgb, vec3(0.0)))) {
            connectToCamera(position, n, shading, -dir, m, powerW);
        }
        if (vertex == bounces + 1u) break;
        vec3 wiHit = -dir;
        // Photon roulette on the albedo: power stays an unbiased flux estimate (radiance's
        // 1/eta^2 across refraction does not apply to flux).
        uint event = scatterPhoton(dir, powerW, shading, m.diffuse.rgb, m.specular,
                                   m.transmissive, frontFace, rng, kRngPcg);
        if (event == kScatterAbsorbed || !isScatterOnGeometricSide(event, dir, n)) break;
        if (shading != n) powerW *= computeShadingAdjoint(wiHit, dir, n, shading);
        float offset = computeRayOffset(position, params.rayFloorM);
        origin = position + (dot(dir, n) >= 0.0 ? n : -n) * offset;
    }
}
