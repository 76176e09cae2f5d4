// A result photon's splat, shared by the instanced splats (splat.vert, splat.frag) and the tiled
// gather (gather_bin.comp, gather.comp): its extents and clip lines, and the weight it gives a
// viewer G-buffer point. The includer declares `photons` (ResultPhoton[]) and `splatClip`
// (vec4[], kClipVec4s per photon) first, or defines ISPM_SPLAT_WEIGHT_ONLY for the weight alone.
#include "constants.glsl"
#include "../shared/splat_clip.h"

#ifndef ISPM_SPLAT_WEIGHT_ONLY
// The splat of result photon `id`: its radius (photon.power.w, set by the density pass; 0 when
// its disc cannot reach the view), extents along +t, -t, +b, -b (the radius, or with clip lines
// (splat_clip) cut to the lines across the basis axes) and clip lines (the nonzero poles first).
struct SplatShape {
    float radius;
    vec4 extent;
    uint lines;      // clip lines in poles
    uint wholeLines; // of them the first, running past the disc both ways (kWedgeOpenBoth)
    vec2 poles[kClipRays];
    uint wedges[kClipRays]; // each line's wedge (findLineWedges)
};

SplatShape loadSplatShape(uint id, uint clipLines) {
    SplatShape s;
    s.radius = photons[id].power.w;
    s.extent = vec4(s.radius);
    s.lines = 0u;
    s.wholeLines = 0u;
    for (uint i = 0u; i < kClipRays; ++i) {
        s.poles[i] = vec2(0.0);
        s.wedges[i] = kWedgeOpenBoth;
    }
    if (clipLines != 0u && s.radius > 0.0) {
        // Packed by the density pass (writeClip): the whole lines, the bounded ones, zero poles.
        s.extent = splatClip[id * kClipVec4s + kClipRays / 2u];
        for (uint i = 0u; i < kClipRays; ++i) {
            vec4 two = splatClip[id * kClipVec4s + i / 2u];
            s.poles[i] = i % 2u == 0u ? two.xy : two.zw;
            s.wedges[i] = uint(splatClip[id * kClipVec4s + kClipRays / 2u + 1u + i / 4u][i % 4u]);
            bool line = dot(s.poles[i], s.poles[i]) > 0.0;
            s.lines += line ? 1u : 0u;
            s.wholeLines += line && s.wedges[i] == kWedgeOpenBoth ? 1u : 0u;
        }
    }
    return s;
}

// The shape's line counts in one uint, as the splat hands them on (a flat varying, the gather's
// shared memory) to computeSplatWeight: the lines, and the whole ones << 8.
uint packLineCounts(SplatShape s) { return s.lines | (s.wholeLines << 8u); }
#endif

// The splat's kernel 2 / (pi r^2) (1 - s^2 / r^2) over the in-plane distance s at G-buffer point
// `position` with normal `n`, or a negative value when the point receives nothing: it faces away
// from where the photon arrived or lies outside the photon's ellipsoid (radius in the plane,
// radius x squash along the normal `pn`). The kernel integrates to 1 over the disc of radius r:
// one photon's power is conserved on a flat surface. `x` is the point's offset in the splat
// basis (tangent, bitangent).
float computeSplatKernel(vec4 centre, vec3 pn, vec3 tangent, vec3 bitangent, float squash,
                         vec3 position, vec3 n, out vec2 x) {
    x = vec2(0.0);
    if (dot(n, pn) <= 0.0) return -1.0;
    float radius = centre.w;
    vec3 d = position - centre.xyz;
    float along = dot(d, pn);
    vec3 inPlane = d - along * pn;
    float s2 = dot(inPlane, inPlane) / (radius * radius);
    float z = along / (radius * squash);
    if (s2 + z * z > 1.0) return -1.0;
    x = vec2(dot(inPlane, tangent), dot(inPlane, bitangent));
    return 2.0 * kInvPi / (radius * radius) * (1.0 - s2);
}

// The kernel over the kept mass, or a negative value where computeSplatKernel gives none or the
// point lies beyond a clip line (in its wedge); `lineCounts` as packLineCounts gives them.
// Gather-style renormalisation: the pixel's own disc (radius r, centred on it) is cut by the
// same lines; dividing by the part of it that lies on the surface keeps a uniform irradiance
// uniform up to the wall, and the photon's power on the surfaces it reached. Without lines the kept mass is 1: splat.frag's variant for discs without clip lines
// (splat_clip off, SPLAT_CLIP_LINES 0) calls computeSplatKernel alone, since llvmpipe runs this
// loop's body once even for no line.
float computeSplatWeight(vec4 centre, vec3 pn, vec3 tangent, vec3 bitangent, uint lineCounts,
                         vec2 poles[kClipRays], uint wedges[kClipRays], float squash,
                         vec3 position, vec3 n) {
    vec2 x;
    float kernel = computeSplatKernel(centre, pn, tangent, bitangent, squash, position, n, x);
    if (kernel < 0.0) return -1.0;
    float keptMass = computeKeptMass(x, poles, wedges, lineCounts >> 8u, lineCounts & 0xffu, centre.w);
    if (keptMass < 0.0) return -1.0; // beyond a clip line
    return kernel / keptMass;
}
