// Direct light averaged over a pixel's area where it changes inside the pixel (the pixels
// edge_find.comp listed): rays from the eye through points spread over the pixel (the first two
// Sobol dimensions, a (0,2)-sequence, Owen-scrambled per pixel and frame: any 2^k of them are
// stratified along x and along y, so a straight edge is sampled evenly), the setting's number of
// them halved as often as the list says (a pixel whose light changes little against its own
// takes a half or a quarter), each shaded as direct.frag shades a pixel's centre (every light,
// the same shadow test); their mean replaces the pixel's direct light, and alpha the share that
// hit a surface (compose.frag shows the background in the rest). The reference path tracer's box
// filter, so silhouettes, creases and shadow edges come out as it draws them. With EDGE_EMISSION 1
// (a scene with an emitter) the rays add what the emitters they hit show, and the pixel's own
// emission (which compose.frag adds) is taken off their mean, so a lamp's outline is averaged
// over the pixel like a shadow's.
//
// kDirectEdgeLanes invocations share a pixel, each taking every kDirectEdgeLanes-th sample: rays
// through one pixel take the same way through the BVH side by side. They look for their surface
// among the instances the G-buffer shows at the pixel and its eight neighbours (a box or two
// instead of every instance the ray's path passes near); where one of those shows the
// background, through the whole BVH, since a sliver of an instance no pixel centre shows (the
// far ground beyond a roof's edge) may lie between. A sliver between two shown surfaces (the
// seam of two boxes) is the one thing missed: the surface behind it is shaded instead.
#ifndef EDGE_EMISSION
#define EDGE_EMISSION 0
#endif
#include "lib/scene_buffers.glsl"
// Before bvh.glsl, for its computeHitShadingNormal.
#include "lib/vertex_attributes.glsl"
#include "lib/frame_constants.glsl"
#include "lib/scene_textures.glsl"
#include "lib/bvh.glsl"
#include "lib/brdf.glsl"
#include "lib/lights.glsl"
#include "lib/direct_light.glsl"
#include "lib/emitters.glsl"
#include "lib/environment.glsl"
#include "shared/photon_scatter.h"

#include "lib/viewer_gbuffer.glsl"

layout(local_size_x = kDirectEdgeGroupSize) in;
layout(binding = kImageDirect, rgba32f) uniform writeonly image2D uDirectImage;
layout(std430, binding = kBindingDirectEdges) readonly buffer DirectEdges {
    DirectEdgeHeader header;
    uint edgePixels[];
};
layout(std140, binding = kBindingPassParams) uniform DirectEdgeParamsBlock { DirectEdgeParams params; };

shared vec4 laneSums[kDirectEdgeGroupSize];

// The instances the pixel and its eight neighbours show (each once), and whether one of them
// shows the background.
const uint kMaxShown = 9u;
uint shownInstances[kMaxShown];
uint shownCount = 0u;
bool showsBackground = false;

void findShownInstances(ivec2 pixel) {
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = clamp(pixel + ivec2(dx, dy), ivec2(0), ivec2(frame.imageSizePx) - 1);
            float shown = texelFetch(uPosition, q, 0).w; // instance + 1; 0: the background
            showsBackground = showsBackground || shown < 0.5;
            if (shown < 0.5) continue;
            uint instance = uint(shown) - 1u;
            bool known = false;
            for (uint k = 0u; k < shownCount; ++k) known = known || shownInstances[k] == instance;
            if (!known) shownInstances[shownCount++] = instance;
        }
    }
}

// The closest hit along the ray among the shown instances, or the whole BVH's.
bool traceEdgeRay(vec3 origin, vec3 dir, out RayHit hit) {
    if (showsBackground) return traceRay(origin, dir, kNoHitDistance, hit);
    hit.t = kNoHitDistance;
    bool found = false;
    for (uint k = 0u; k < shownCount; ++k)
        found = intersectInstance(shownInstances[k], origin, dir, hit, false) || found;
    return found;
}

// Bounce slot of seedRandom for a pixel's scrambling seeds (photon = pixel index).
const uint kEdgeSeedSlot = 0xfffffffdu;

// The direct light seen through image point `point` (pixels from the lower left), and whether a
// surface was hit; the emitters' from samples [firstEmitterSample, + emitterSamples) of the
// pixel's sequence.
vec3 shadeThrough(vec2 point, float rayFloorM, uint firstEmitterSample, uint emitterSamples,
                  uvec3 emitterSeeds, out bool hitSurface) {
    // From the near plane on, as the G-buffer sees the scene.
    vec3 toNear = computeEyeToNear(point);
    vec3 origin = frame.cameraPosW + toNear;
    vec3 dir = normalize(toNear);
    RayHit hit;
    hitSurface = traceEdgeRay(origin, dir, hit);
    if (!hitSurface) return vec3(0.0);
    vec3 position = origin + dir * hit.t;
    vec3 geometric = computeHitNormal(hit);
    vec3 n = dot(geometric, dir) < 0.0 ? geometric : -geometric; // faces the eye, as the G-buffer's
    // A ray's hit knows its geometric normal: it decides sides here, unlike at the pixel's
    // centre (direct.frag), whose G-buffer holds the shading normal alone.
    vec3 shading = computeHitShadingNormal(hit, n);
    GpuMaterial m = materials[triangles[hit.triangle].w];
    vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
    vec3 radiance =
        computeShadedDirectRadiance(position, n, shading, diffuse, m.specular, -dir, rayFloorM) +
        computeEmitterRadiance(position, n, shading, diffuse, m.specular, -dir, rayFloorM,
                               firstEmitterSample, emitterSamples, emitterSeeds) +
        computeEnvironmentRadiance(position, n, shading, diffuse, m.specular, -dir, rayFloorM,
                                   firstEmitterSample, emitterSamples, emitterSeeds.zxy);
#if EDGE_EMISSION
    radiance += computeEmittedRadiance(m.emission, -dot(geometric, dir));
#endif
    return radiance;
}

void main() {
    uint lane = gl_LocalInvocationID.x % kDirectEdgeLanes;
    uint index = gl_WorkGroupID.x * kDirectEdgePixelsPerGroup + gl_LocalInvocationID.x / kDirectEdgeLanes;
    bool listed = index < header.pixels;
    uint entry = listed ? edgePixels[index] : 0u;
    uint at = entry & ((1u << kDirectEdgeHalvingShift) - 1u);
    uint width = uint(frame.imageSizePx.x);
    ivec2 pixel = ivec2(at % width, at / width);
    uint samples = listed ? max(params.samplesPerPixel >> (entry >> kDirectEdgeHalvingShift), 1u) : 0u;
    vec4 sum = vec4(0.0); // radiance, surface hits
    if (samples > lane) {
        findShownInstances(pixel);
        uint rng = seedRandom(at, kEdgeSeedSlot, frame.seed);
        uint seedX = hashPcg(rng);
        uint seedY = hashPcg(seedX);
        float rayFloorM = params.rayFloorM;
        // The emitters' samples shared out among the pixel's rays: about area_samples in all,
        // as direct.frag takes at the pixel's centre.
        uint emitterSamples = max(frame.areaSamples / samples, 1u);
        uvec3 emitterSeeds = computeEmitterSeeds(at, kEmitterSeedSlot);
        for (uint i = lane; i < samples; i += kDirectEdgeLanes) {
            bool hitSurface;
            uvec2 bits = computeSobolBits(i).xy;
            vec2 u = vec2(uvec2(scrambleOwen(bits.x, seedX), scrambleOwen(bits.y, seedY)) >> 8u) *
                     (1.0 / 16777216.0);
            sum.rgb += shadeThrough(vec2(pixel) + u, rayFloorM, i * emitterSamples, emitterSamples,
                                    emitterSeeds, hitSurface);
            sum.a += hitSurface ? 1.0 : 0.0;
        }
    }
    laneSums[gl_LocalInvocationID.x] = sum;
    barrier();
    if (!listed || lane != 0u) return;
    for (uint k = 1u; k < kDirectEdgeLanes; ++k) sum += laneSums[gl_LocalInvocationID.x + k];
    sum /= float(samples);
#if EDGE_EMISSION
    sum.rgb -= texelFetch(uEmission, pixel, 0).rgb; // compose.frag adds it back
#endif
    imageStore(uDirectImage, pixel, sum);
}
