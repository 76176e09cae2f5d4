// Direct light averaged over a pixel's area where it changes inside the pixel (the pixels
// edge_find.comp listed): rays from the eye through points spread over the pixel (the first two
// Sobol dimensions, a (0,2)-sequence, Owen-scrambled per pixel and frame: any 2^k of them are
// stratified along x and along y, so a straight edge is sampled evenly), the setting's number of
// them halved as often as the list says (a pixel whose light changes little against its own
// takes a half or a quarter), each shaded as direct.frag shades a pixel's centre (every light,
// the same shadow test); their mean replaces the pixel's direct light, and alpha the share that
// hit a surface (compose.frag shows the background in the rest). The reference path tracer's box
// filter, so silhouettes, creases and shadow edges come out as it draws them. Emission stays the
// centre's (compose.frag).
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/bvh.glsl"
#include "lib/scene_textures.glsl"
#include "lib/brdf.glsl"
#include "lib/lights.glsl"
#include "lib/direct_light.glsl"
#include "shared/photon_scatter.h"

layout(local_size_x = kDirectEdgeGroupSize) in;
layout(binding = kImageDirect, rgba32f) uniform writeonly image2D uDirectImage;
layout(std430, binding = kBindingDirectEdges) readonly buffer DirectEdges {
    DirectEdgeHeader header;
    uint edgePixels[];
};
layout(std140, binding = kBindingPassParams) uniform DirectEdgeParamsBlock { DirectEdgeParams params; };

// Bounce slot of seedRandom for a pixel's scrambling seeds (photon = pixel index).
const uint kEdgeSeedSlot = 0xfffffffdu;

// The direct light seen through image point `point` (pixels from the lower left), and whether a
// surface was hit.
vec3 shadeThrough(vec2 point, float rayFloorM, out bool hitSurface) {
    // From the near plane on, as the G-buffer sees the scene.
    vec3 toNear = computeEyeToNear(point);
    vec3 origin = frame.cameraPosition.xyz + toNear;
    vec3 dir = normalize(toNear);
    RayHit hit;
    hitSurface = traceRay(origin, dir, kNoHitDistance, hit);
    if (!hitSurface) return vec3(0.0);
    vec3 position = origin + dir * hit.t;
    vec3 geometric = computeHitNormal(hit);
    vec3 n = dot(geometric, dir) < 0.0 ? geometric : -geometric; // faces the eye, as the G-buffer's
    GpuMaterial m = materials[triangles[hit.triangle].w];
    vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
    return computeDirectRadiance(position, n, diffuse, m.specular, -dir, rayFloorM);
}

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= header.pixels) return;
    uint listed = edgePixels[index];
    uint at = listed & ((1u << kDirectEdgeHalvingShift) - 1u);
    uint width = uint(frame.imageSize.x);
    ivec2 pixel = ivec2(at % width, at / width);
    uint rng = seedRandom(at, kEdgeSeedSlot, frame.counts.z);
    uint seedX = hashPcg(rng);
    uint seedY = hashPcg(seedX);
    uint samples = max(params.control.x >> (listed >> kDirectEdgeHalvingShift), 1u);
    float rayFloorM = uintBitsToFloat(params.control.y);
    vec3 sum = vec3(0.0);
    float covered = 0.0;
    for (uint i = 0u; i < samples; ++i) {
        bool hitSurface;
        uvec2 bits = computeSobolBits(i).xy;
        vec2 u = vec2(uvec2(scrambleOwen(bits.x, seedX), scrambleOwen(bits.y, seedY)) >> 8u) *
                 (1.0 / 16777216.0);
        sum += shadeThrough(vec2(pixel) + u, rayFloorM, hitSurface);
        covered += hitSurface ? 1.0 : 0.0;
    }
    imageStore(uDirectImage, pixel, vec4(sum, covered) / float(samples));
}
