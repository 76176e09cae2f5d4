// Splat vertex stage: one instance per result photon, aligned with the photon's surface normal.
// splat_shape disc: a flat square of side 2r in the surface plane (cut to the clip extents), which
// covers each pixel once; box (the thesis's): radius r in the plane and r * squash along the
// normal, only back faces kept (front faces culled), which cover the box's footprint once,
// camera inside or out.
#include "lib/frame_constants.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"
#include "splat/splat_radius.glsl"

layout(std430, binding = kBindingResultPhotons) readonly buffer ResultBuffer { ResultPhoton photons[]; };
layout(std430, binding = kBindingPhotonCounters) readonly buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatClip) readonly buffer SplatClip { vec4 splatClip[]; };

// Everything the fragment stage needs of the photon, constant over its box: read and derived once
// per corner here rather than once per covered pixel.
flat out vec4 vCentre;   // xyz = position (m), w = radius (m)
flat out vec3 vNormal;   // the photon's surface normal
flat out vec3 vTangent;  // the splat basis (buildSplatBasis)
flat out vec3 vBitangent;
flat out vec3 vPower;    // W
flat out vec3 vIncoming; // the direction the photon arrived along
flat out uint vLines;    // clip lines in vPoles (the nonzero poles first)
flat out vec2 vPoles[kClipRays];

// The draw is indexed (splat_pass.cpp holds the triangles). Box: gl_VertexID is the cube corner,
// its x from bit 0, y from bit 1, z from bit 2 of the index, each -1 or +1.

// Disc: corner i (0 to 3, counter-clockwise from (+t, +b)) of the square round the disc in its
// plane, cut to the extents where walls cut the disc. Two triangles: an octagon's six fan
// triangles cover fewer pixels but cost more in the rasteriser than they save (llvmpipe: a
// splat is a few pixels across, and each triangle edge is a row of partly covered blocks).
vec3 computeDiscCorner(uint i, vec3 t, vec3 b, vec4 extent) {
    vec2 sign2 = vec2(i == 0u || i == 3u ? 1.0 : -1.0, i < 2u ? 1.0 : -1.0);
    vec2 corner = sign2 * vec2(sign2.x > 0.0 ? extent.x : extent.y, sign2.y > 0.0 ? extent.z : extent.w);
    return t * corner.x + b * corner.y;
}

void main() {
    uint stored = counters.splatDraw.y;
    uint id = stored * params.control.z / params.control.w + uint(gl_InstanceID);
    ResultPhoton photon = photons[id];
    vec3 n = photon.normalDensity.xyz;
    vec3 t;
    vec3 b;
    buildSplatBasis(n, t, b);
    float radius = computeSplatRadius(photon);
    // Without clip lines (travel radii) nothing is cut. The box shrinks to the lines across the
    // basis axes (a box scene's walls); a photon culled by the density pass (radius 0, its clip
    // data not written) collapses to a point and draws nothing.
    vec4 extent = vec4(radius); // along +t, -t, +b, -b
    // Density radii come with clip lines (the density pass); travel radii without.
    vLines = 0u;
    for (uint i = 0u; i < kClipRays; ++i) vPoles[i] = vec2(0.0);
    if (getRadiusMode() == kRadiusDensity && radius > 0.0) {
        extent = splatClip[id * kClipVec4s + kClipRays / 2u];
        for (uint i = 0u; i < kClipRays / 2u; ++i) {
            vec4 two = splatClip[id * kClipVec4s + i];
            if (dot(two.xy, two.xy) > 0.0) vPoles[vLines++] = two.xy;
            if (dot(two.zw, two.zw) > 0.0) vPoles[vLines++] = two.zw;
        }
    }
    vec3 world;
    if (params.control.y == kSplatShapeBox) {
        vec3 c = vec3((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0,
                      (gl_VertexID & 4) != 0 ? 1.0 : -1.0);
        float alongT = c.x > 0.0 ? extent.x : extent.y;
        float alongB = c.y > 0.0 ? extent.z : extent.w;
        world = photon.positionDistance.xyz +
                (t * (c.x * alongT) + b * (c.y * alongB) + n * (c.z * radius * params.shape.x));
    } else {
        world = photon.positionDistance.xyz + computeDiscCorner(uint(gl_VertexID), t, b, extent);
    }
    vCentre = vec4(photon.positionDistance.xyz, radius);
    vNormal = n;
    vTangent = t;
    vBitangent = b;
    vPower = photon.power.rgb;
    vIncoming = photon.incoming.xyz;
    gl_Position = toBlockClip(frame.clipFromWorld * vec4(world, 1.0), int(params.shape.y));
}
