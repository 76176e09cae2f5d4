// Splat vertex stage: one instanced box per result photon, aligned with the photon's surface
// normal, radius r in the surface plane and r * squash along the normal. Only back faces are kept
// (front faces culled): they cover the box's screen footprint once, camera inside or out.
#include "lib/frame_constants.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"
#include "splat/splat_radius.glsl"

layout(std430, binding = kBindingResultPhotons) readonly buffer ResultBuffer { ResultPhoton photons[]; };
layout(std430, binding = kBindingPhotonCounters) readonly buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatClip) readonly buffer SplatClip { vec4 splatClip[]; };

layout(location = 0) uniform uvec2 uPass; // x = this pass, y = pass count

flat out uint vPhoton;
flat out float vRadius;
flat out vec4 vClip[kClipRays / 2u]; // clip lines, two poles a vec4 (shared/splat_clip.h)

// Unit cube corners and its 12 triangles, counter-clockwise seen from outside.
const vec3 kCorners[8] = vec3[8](vec3(-1, -1, -1), vec3(1, -1, -1), vec3(-1, 1, -1), vec3(1, 1, -1),
                                 vec3(-1, -1, 1), vec3(1, -1, 1), vec3(-1, 1, 1), vec3(1, 1, 1));
const int kIndices[36] = int[36](0, 2, 1, 1, 2, 3,  4, 5, 6, 5, 7, 6,  0, 1, 4, 1, 5, 4,
                                 2, 6, 3, 3, 6, 7,  0, 4, 2, 2, 4, 6,  1, 3, 5, 3, 7, 5);

void main() {
    uint stored = counters.splatDraw.y;
    uint id = stored * uPass.x / uPass.y + uint(gl_InstanceID);
    ResultPhoton photon = photons[id];
    vec3 n = photon.normalDensity.xyz;
    vec3 t;
    vec3 b;
    buildSplatBasis(n, t, b);
    float radius = computeSplatRadius(photon);
    // Without clip lines (travel radii) nothing is cut. The box shrinks to the lines across the
    // basis axes (a box scene's walls); a photon culled by the density pass (radius 0) collapses
    // to a point and draws nothing.
    vec4 extent = vec4(radius); // along +t, -t, +b, -b
    for (uint i = 0u; i < kClipRays / 2u; ++i) {
        vClip[i] = uSplatShape.w > 0.5 ? splatClip[id * (kClipRays / 2u) + i] : vec4(0.0);
        for (uint k = 0u; k < 2u; ++k) {
            vec2 pole = k == 0u ? vClip[i].xy : vClip[i].zw;
            float c = length(pole);
            if (c <= 0.0) continue;
            vec2 axis = pole / c;
            const float kAlong = 0.999; // a line across an axis, not a slanted one
            if (axis.x > kAlong) extent.x = min(extent.x, c);
            if (-axis.x > kAlong) extent.y = min(extent.y, c);
            if (axis.y > kAlong) extent.z = min(extent.z, c);
            if (-axis.y > kAlong) extent.w = min(extent.w, c);
        }
    }
    vec3 c = kCorners[kIndices[gl_VertexID]];
    float alongT = c.x > 0.0 ? extent.x : extent.y;
    float alongB = c.y > 0.0 ? extent.z : extent.w;
    vec3 world = photon.positionDistance.xyz +
                 (t * (c.x * alongT) + b * (c.y * alongB) + n * (c.z * radius * uSplatShape.z));
    vPhoton = id;
    vRadius = radius;
    gl_Position = frame.clipFromWorld * vec4(world, 1.0);
}
