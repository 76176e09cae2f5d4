// Tiled gather: one workgroup per tile of the splat buffer, one invocation per pixel. The tile's
// photons are staged in shared memory kGatherBatch at a time; each pixel adds BRDF x power x the
// splat's weight (lib/splat_kernel.glsl) of every photon whose ellipsoid holds its G-buffer point,
// as splat.frag does for the fragments of a box splat (splat_shape box).
#include "lib/frame_constants.glsl"
#include "lib/brdf.glsl"
#include "shared/gather_data.h"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"

layout(local_size_x = kGatherTilePx, local_size_y = kGatherTilePx) in;

layout(std430, binding = kBindingResultPhotons) readonly buffer ResultBuffer { ResultPhoton photons[]; };
layout(std430, binding = kBindingSplatClip) readonly buffer SplatClip { vec4 splatClip[]; };
layout(std430, binding = kBindingGatherTiles) readonly buffer TileBuffer {
    uvec4 header;
    GatherTile tiles[];
};
layout(std430, binding = kBindingGatherList) readonly buffer ListBuffer { uint list[]; };
layout(std140, binding = kBindingPassParams) uniform GatherParamsBlock { GatherParams params; };
layout(rgba32f, binding = kImageGatherOutput) uniform writeonly image2D uOutput;

#include "lib/viewer_gbuffer.glsl"
#include "lib/splat_kernel.glsl"

shared vec4 sCentre[kGatherBatch];    // xyz position, w radius
shared vec4 sNormal[kGatherBatch];    // xyz normal, w = packLineCounts (uint bits)
shared vec4 sTangent[kGatherBatch];
shared vec4 sBitangent[kGatherBatch];
shared vec4 sPower[kGatherBatch];
shared vec4 sIncoming[kGatherBatch];
shared vec4 sPoles[kGatherBatch][kClipRays / 2u];
shared uvec4 sWedges[kGatherBatch][kClipRays / 4u];

void stagePhoton(uint slot, uint id) {
    SplatShape shape = loadSplatShape(id, params.clipLines);
    vec3 n = photons[id].normalDensity.xyz;
    vec3 t;
    vec3 b;
    buildSplatBasis(n, t, b);
    sCentre[slot] = vec4(photons[id].positionDistance.xyz, shape.radius);
    sNormal[slot] = vec4(n, uintBitsToFloat(packLineCounts(shape)));
    sTangent[slot] = vec4(t, 0.0);
    sBitangent[slot] = vec4(b, 0.0);
    sPower[slot] = vec4(photons[id].power.rgb, 0.0);
    sIncoming[slot] = vec4(photons[id].incoming.xyz, 0.0);
    for (uint i = 0u; i < kClipRays / 2u; ++i)
        sPoles[slot][i] = vec4(shape.poles[2u * i], shape.poles[2u * i + 1u]);
    for (uint i = 0u; i < kClipRays / 4u; ++i)
        sWedges[slot][i] = uvec4(shape.wedges[4u * i], shape.wedges[4u * i + 1u],
                                 shape.wedges[4u * i + 2u], shape.wedges[4u * i + 3u]);
}

void main() {
    uvec2 tileXY = gl_WorkGroupID.xy;
    uint tile = tileXY.y * params.tiles.x + tileXY.x;
    uint count = tiles[tile].counts.x;
    uint first = tiles[tile].counts.y;
    ivec2 pixel = ivec2(tileXY * kGatherTilePx + gl_LocalInvocationID.xy);
    bool inside = all(lessThan(pixel, ivec2(params.bufferSizePx)));
    ivec2 g = getBlockGBufferPixel(pixel, int(params.pixelsPerBufferPx));
    vec4 position = inside ? texelFetch(uPosition, g, 0) : vec4(0.0);
    bool receives = inside && position.w >= 0.5;
    vec3 n = receives ? texelFetch(uNormal, g, 0).xyz : vec3(0.0);
    vec3 diffuse = receives ? texelFetch(uDiffuse, g, 0).rgb : vec3(0.0);
    vec4 specular = receives ? texelFetch(uSpecular, g, 0) : vec4(0.0);
    vec3 wo = normalize(frame.cameraPosW - position.xyz);
    vec4 sum = vec4(0.0);
    uint local = gl_LocalInvocationIndex;
    for (uint base = 0u; base < count; base += kGatherBatch) {
        uint batch = min(kGatherBatch, count - base);
        barrier();
        if (local < batch) stagePhoton(local, list[first + base + local]);
        barrier();
        if (!receives) continue;
        for (uint j = 0u; j < batch; ++j) {
            // The ellipsoid lies in the sphere of radius r max(1, squash): most of a tile's
            // photons miss the pixel, and leave here.
            vec3 d = position.xyz - sCentre[j].xyz;
            float reach = sCentre[j].w * max(1.0, params.squash);
            if (dot(d, d) > reach * reach) continue;
            vec2 poles[kClipRays];
            uint wedges[kClipRays];
            for (uint i = 0u; i < kClipRays / 2u; ++i) {
                poles[2u * i] = sPoles[j][i].xy;
                poles[2u * i + 1u] = sPoles[j][i].zw;
            }
            for (uint i = 0u; i < kClipRays; ++i) wedges[i] = sWedges[j][i / 4u][i % 4u];
            float weight = computeSplatWeight(sCentre[j], sNormal[j].xyz, sTangent[j].xyz,
                                              sBitangent[j].xyz, floatBitsToUint(sNormal[j].w),
                                              poles, wedges, params.squash, position.xyz, n);
            if (weight < 0.0) continue;
            vec3 f = evaluateSplatBrdf(diffuse, specular, n, -sIncoming[j].xyz, wo,
                                           frame.specularTraceMinExponent);
            sum += vec4(f * sPower[j].rgb * weight, 1.0);
        }
    }
    if (inside) imageStore(uOutput, pixel, sum);
}
