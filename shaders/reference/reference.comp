// Reference path tracer (one sample per pixel per dispatch, accumulated): camera paths through
// the same BVH, materials and lights as the photon mapper. Next-event estimation to every light
// with a shadow ray at each vertex (point, spot and sun lights are delta lights: paths cannot hit
// them), BSDF sampling by the shared scatterSurface, Russian roulette after a few vertices.
// `bounces` B counts reflections between the light and the visible surface, as in ispm mode:
// light is gathered at vertices 1..B+1 and the path stops there.
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/scene_textures.glsl"
#include "lib/bvh.glsl"
#include "lib/brdf.glsl"
#include "lib/lights.glsl"
#define SHADOW_RAYS 1 // next-event estimation: a shadow ray per light
#include "lib/direct_light.glsl"
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
    for (uint vertex = 1u; ; ++vertex) {
        RayHit hit;
        if (!traceRay(origin, dir, kNoHitDistance, hit)) {
            if (vertex == 1u) radiance += frame.backgroundRadiance; // the background lights nothing
            break;
        }
        vec3 position = origin + dir * hit.t;
        vec3 geometric = computeHitNormal(hit);
        bool frontFace = dot(geometric, dir) < 0.0;
        vec3 n = frontFace ? geometric : -geometric;
        GpuMaterial m = materials[triangles[hit.triangle].w];
        vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
        if (vertex == 1u) radiance += m.emission.rgb; // emission is seen, it lights nothing
        vec3 wo = -dir;
        radiance += throughput * computeDirectRadiance(position, n, diffuse, m.specular, wo,
                                                       params.rayOffsetM);
        float offset = computeRayOffset(position, params.rayOffsetM);
        if (vertex > bounces) break;
        float total = computeLobeAlbedo(diffuse, m.specular, m.transmissive);
        if (total <= 0.0) break;
        uint event = scatterSurface(dir, throughput, n, diffuse, m.specular, m.transmissive,
                                    frontFace, rng, kRngPcg, 1.0 / total);
        if (event == kScatterAbsorbed) break;
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
