// Splat vertex stage: one instance per result photon, aligned with the photon's surface normal.
// splat_shape disc: a flat square of side 2r in the surface plane (cut to the clip extents), which
// covers each pixel once; box (the thesis's): radius r in the plane and r * squash along the
// normal, only back faces kept (front faces culled), which cover the box's footprint once,
// camera inside or out.
#include "lib/frame_constants.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"

layout(std430, binding = kBindingResultPhotons) readonly buffer ResultBuffer { ResultPhoton photons[]; };
layout(std430, binding = kBindingPhotonCounters) readonly buffer CounterBuffer { PhotonCounters counters; };
layout(std430, binding = kBindingSplatClip) readonly buffer SplatClip { vec4 splatClip[]; };
layout(std140, binding = kBindingPassParams) uniform SplatParamsBlock { SplatParams params; };
layout(std430, binding = kBindingCausticList) readonly buffer CausticList {
    uvec4 causticDraw[kSplatDrawUvec4s];
    uint causticPhotons[];
};
layout(std430, binding = kBindingDiscList) readonly buffer DiscList {
    uvec4 discCount; // x
    uint discPhotons[];
};

#include "lib/splat_kernel.glsl"

// Everything the fragment stage needs of the photon, constant over its box: read and derived once
// per corner here rather than once per covered pixel.
flat out vec4 vCentre;   // xyz = position (m), w = radius (m)
flat out vec3 vNormal;   // the photon's surface normal
flat out vec3 vTangent;  // the splat basis (buildSplatBasis)
flat out vec3 vBitangent;
flat out vec3 vPower;    // W
flat out vec3 vIncoming; // the direction the photon arrived along
#if SPLAT_CLIP_LINES // splat_clip (SplatPass)
flat out uint vLines;    // clip lines in vPoles (packLineCounts)
flat out vec2 vPoles[kClipRays];
flat out uint vWedges[kClipRays];
#endif

// The draw is indexed (splat_pass.cpp holds the triangles): gl_VertexID is the corner, its
// t side from bit 0, b side from bit 1 and normal side from bit 2 of the index, each -1 or +1.
// The disc uses corners 0-3 and lies in the surface plane; the box all 8.

void main() {
    // The caustic draw's instances are the density pass's list of caustic photons in view; in
    // radius_mode density the other draws' are its list of discs, each draw a slice of it.
    uint listed = params.discList != 0u ? discCount.x : counters.splatDraw.y;
    uint first = computeSliceRange(listed, params.draw, params.drawCount).x + uint(gl_InstanceID);
    uint id = params.photons == kSplatCausticPhotons ? causticPhotons[gl_InstanceID]
              : params.discList != 0u                 ? discPhotons[first]
                                                       : first;
    ResultPhoton photon = photons[id];
    vec3 n = photon.normalDensity.xyz;
    vec3 t;
    vec3 b;
    buildSplatBasis(n, t, b);
    // Every radius mode's radius, from the density pass; 0 for a photon whose disc cannot reach
    // the view: it collapses to a point and draws nothing. With splat_clip discs come with clip lines:
    // the box or square shrinks to the lines across the basis axes (a box scene's walls), and
    // the fragment stage drops what lies beyond any line.
    SplatShape shape = loadSplatShape(id, params.clipLines);
    // A photon this draw does not take (the caustic photons are drawn apart) collapses too.
    if (!isSplatTaken(params.photons, photon.normalDensity.w)) {
        shape.radius = 0.0;
        shape.extent = vec4(0.0);
    }
    float radius = shape.radius;
    vec4 extent = shape.extent; // along +t, -t, +b, -b
#if SPLAT_CLIP_LINES
    vLines = packLineCounts(shape);
    vPoles = shape.poles;
    vWedges = shape.wedges;
#endif
    vec3 c = vec3((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0,
                  (gl_VertexID & 4) != 0 ? 1.0 : -1.0);
    float alongT = c.x > 0.0 ? extent.x : extent.y;
    float alongB = c.y > 0.0 ? extent.z : extent.w;
    float thickness = params.shape == kSplatShapeBox ? radius * params.squash : 0.0;
    vec3 world = photon.positionDistance.xyz + t * (c.x * alongT) + b * (c.y * alongB) + n * (c.z * thickness);
    vCentre = vec4(photon.positionDistance.xyz, radius);
    vNormal = n;
    vTangent = t;
    vBitangent = b;
    vPower = photon.power.rgb;
    vIncoming = photon.incoming.xyz;
    gl_Position = toBlockClip(frame.clipFromWorld * vec4(world, 1.0), params.pixelsPerBufferPx);
}
