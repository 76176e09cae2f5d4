// Reference path tracer (one sample per pixel per dispatch, accumulated): camera paths through
// the same BVH, materials and lights as the photon mapper. Next-event estimation to every light
// with a shadow ray at each vertex (point, spot and sun lights are delta lights: paths cannot hit
// them), and to one point on the emitting triangles picked by power (lib/emitters.glsl), whose
// light a BSDF-sampled ray that hits an emitter gathers too: the two weighed by the power
// heuristic (MIS), so that small bright emitters and large dim ones both converge. BSDF sampling
// by the shared scatterSurface, Russian roulette after a few vertices. An image environment is
// sampled the same way: a direction from the map's pdf at each vertex, MIS with the BSDF-sampled
// ray that leaves the scene.
// `bounces` B counts reflections between the light and the visible surface, as in ispm mode:
// light is gathered at vertices 1..B+1 and the path stops there.
#include "lib/scene_buffers.glsl"
// Before bvh.glsl, for its computeHitShadingNormal.
#include "lib/vertex_attributes.glsl"
#include "lib/frame_constants.glsl"
#include "lib/scene_textures.glsl"
#include "lib/bvh.glsl"
#include "lib/brdf.glsl"
#include "lib/lights.glsl"
#define SHADOW_RAYS 1 // next-event estimation: a shadow ray per light
#include "lib/direct_light.glsl"
#include "lib/emitters.glsl"
#include "lib/environment.glsl"
#include "shared/photon_scatter.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform image2D uAccumulation;

layout(std140, binding = kBindingPassParams) uniform ReferenceParamsBlock { ReferenceParams params; };

const uint kRouletteDepth = 3u;      // vertices traced with certainty before roulette starts
const float kMaxSurvival = 0.95;     // even bright paths end eventually

vec3 traceCameraPath(vec2 pixel, inout uint rng) {
    vec3 origin = frame.cameraPosW;
    vec3 dir = normalize(computeEyeToNear(pixel));
    vec3 radiance = vec3(0.0);
    vec3 throughput = vec3(1.0);
    uint bounces = params.bounces;
    // The pdf of the direction the path left its last vertex by; 0 for the eye's ray and a
    // mirror's or glass's (delta) directions, whose emitter hits light sampling cannot find.
    float lastPdf = 0.0;
    // The last vertex itself (the ray leaves from `origin`, moved off it by the ray offset):
    // the light pdf of an emitter the ray hits is the one sampleEmitter gave from there.
    vec3 lastPosition = origin;
    for (uint vertex = 1u; ; ++vertex) {
        RayHit hit;
        if (!traceRay(origin, dir, kNoHitDistance, hit)) {
            // The camera sees the environment, or the background; the environment's light on
            // surfaces comes from its own samples at each vertex (below), so a path that leaves
            // the scene after a bounce adds nothing, but for an image's: its samples come from the
            // map's pdf, which BSDF sampling meets here, weighed by MIS (after a mirror's or
            // glass's delta direction, which the map's samples cannot find, in full).
            if (vertex == 1u) {
                radiance += hasEnvironment() ? lookUpEnvironment(dir) : frame.backgroundRadiance;
            } else if (hasEnvironmentImage()) {
                float weight =
                    lastPdf > 0.0 ? computeMisWeight(lastPdf, computeEnvironmentImagePdf(dir)) : 1.0;
                radiance += throughput * lookUpEnvironment(dir) * weight;
            }
            break;
        }
        vec3 position = origin + dir * hit.t;
        vec3 geometric = computeHitNormal(hit);
        bool frontFace = dot(geometric, dir) < 0.0;
        vec3 n = frontFace ? geometric : -geometric;
        vec3 shading = computeHitShadingNormal(hit, n); // the BRDF's; n decides sides
        GpuMaterial m = materials[triangles[hit.triangle].w];
        vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
        if (any(greaterThan(m.emission.rgb, vec3(0.0)))) {
            float cosAtEmitter = -dot(geometric, dir);
            float weight = 1.0;
            if (lastPdf > 0.0 && frame.emitterCount > 0u) {
                uvec4 tri = triangles[hit.triangle];
                mat4 world = instances[hit.instance].worldFromObject;
                float lightPdf = computeEmitterPdf(m.emission, lastPosition,
                                                   (world * vec4(positions[tri.x].xyz, 1.0)).xyz,
                                                   (world * vec4(positions[tri.y].xyz, 1.0)).xyz,
                                                   (world * vec4(positions[tri.z].xyz, 1.0)).xyz,
                                                   distance(lastPosition, position), cosAtEmitter);
                weight = computeMisWeight(lastPdf, lightPdf);
            }
            radiance += throughput * computeEmittedRadiance(m.emission, cosAtEmitter) * weight;
        }
        vec3 wo = -dir;
        radiance += throughput * computeShadedDirectRadiance(position, n, shading, diffuse,
                                                             m.specular, wo, params.rayOffsetM);
        float total = computeLobeAlbedo(diffuse, m.specular, m.transmissive);
        bool scatters = vertex <= bounces && total > 0.0;
        if (frame.emitterCount > 0u) {
            vec3 u = vec3(nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
            EmitterSample s = sampleEmitter(position, u, params.rayOffsetM);
            vec3 light = shadeEmitterSample(s, position, n, shading, diffuse, m.specular, wo,
                                            params.rayOffsetM);
            // Where the path goes on, BSDF sampling could reach the same point.
            if (scatters && any(greaterThan(light, vec3(0.0)))) {
                light *= computeMisWeight(s.pdf, computeScatterPdf(dir, shading, diffuse, m.specular, s.wi, 1.0 / total));
            }
            radiance += throughput * light;
        }
        if (hasEnvironmentImage()) {
            // An image's light: one direction from the map's pdf with a ray to the open sky,
            // weighed against BSDF sampling by the power heuristic where the path goes on (at
            // the last vertex too: B counts the reflections after the light).
            vec2 u = vec2(nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
            EnvironmentSample s = sampleEnvironmentImage(u);
            if (s.pdf > 0.0) {
                vec3 light = shadeEnvironmentDirection(s.toward, s.radiance, position, n, shading,
                                                       diffuse, m.specular, wo, params.rayOffsetM) /
                             s.pdf;
                if (scatters && any(greaterThan(light, vec3(0.0)))) {
                    light *= computeMisWeight(s.pdf, computeScatterPdf(dir, shading, diffuse, m.specular, s.toward, 1.0 / total));
                }
                radiance += throughput * light;
            }
        } else if (hasEnvironment()) {
            // The environment's light at this vertex: one cosine-weighted direction with a ray
            // to the open sky, as direct.frag samples it (at the last vertex too: B counts the
            // reflections after the light).
            vec3 u = vec3(0.0, nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
            radiance += throughput * shadeEnvironmentSample(u, position, n, shading, diffuse,
                                                            m.specular, wo, params.rayOffsetM);
        }
        float offset = computeRayOffset(position, params.rayOffsetM);
        if (!scatters) break;
        vec3 dirIn = dir;
        uint event = scatterSurface(dir, throughput, shading, diffuse, m.specular,
                                    m.transmissive, frontFace, rng, kRngPcg, 1.0 / total);
        if (event == kScatterAbsorbed || !isScatterOnGeometricSide(event, dir, n)) break;
        lastPdf = event == kScatterDiffuse || event == kScatterSpecular
                      ? computeScatterPdf(dirIn, shading, diffuse, m.specular, dir, 1.0 / total)
                      : 0.0;
        if (event == kScatterRefract) {
            throughput *= computeRefractedRadianceScale(frontFace, m.transmissive.w);
        }
        if (vertex >= kRouletteDepth) {
            float survive = min(max(throughput.r, max(throughput.g, throughput.b)), kMaxSurvival);
            if (nextRandom(rng, kRngPcg) >= survive) break;
            throughput /= survive;
        }
        // Leave on the side the new direction points to (refraction crosses the surface).
        origin = position + (dot(dir, n) >= 0.0 ? n : -n) * offset;
        lastPosition = position;
    }
    return radiance;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uAccumulation);
    if (any(greaterThanEqual(pixel, size))) return;
    uint pixelIndex = uint(pixel.y * size.x + pixel.x);
    uint rng = seedRandom(pixelIndex, params.sampleIndex, params.seed);
    // Box filter: a uniformly jittered position inside the pixel.
    vec2 jitter = vec2(nextRandom(rng, kRngPcg), nextRandom(rng, kRngPcg));
    vec3 radiance = traceCameraPath(vec2(pixel) + jitter, rng);
    vec4 sum = imageLoad(uAccumulation, pixel);
    imageStore(uAccumulation, pixel, sum + vec4(radiance, 1.0));
}
