// What the edge-aware filters on the indirect light share (filter_input.frag, atrous.comp,
// upsample.frag, specular_filter.comp): the viewer G-buffer channels they read, the filter
// guide's encoding, the weight of a tap on a turned surface or off the pixel's plane, and the
// reflectance the light is divided by, so they smooth irradiance and keep texture and colour
// edges. Needs frame_constants.glsl included before.

#include "viewer_gbuffer.glsl"

const float kPlaneFootprints = 1.0; // off-plane distance, in tap footprints, of weight e^-1
const float kMinReflectance = 0.02; // demodulation floor (black surfaces keep their light)

// Normal weight cos^64 (10 degrees apart halves a tap), as six squarings.
float weighNormals(float cosAngle) {
    float w = max(cosAngle, 0.0);
    w *= w;
    w *= w;
    w *= w;
    w *= w;
    w *= w;
    return w * w;
}

vec3 getReflectance(ivec2 g) { return max(texelFetch(uDiffuse, g, 0).rgb, vec3(kMinReflectance)); }

// 1 / (kPlaneFootprints x the distance on the surface of G-buffer pixel g to the nearest of the
// points `step` pixels to its left, right, below and above): the off-plane distance over it is a
// tap's exponent. The nearest, so that a pixel beside a depth edge (a room's inside seen through
// its door) measures its footprint on its own surface, not the step across the edge (which let a
// wall metres in front pass the plane test). A pixel alone on its surface gets no plane test.
float computePlaneScale(ivec2 g, vec3 position, int step) {
    ivec2 size = ivec2(frame.imageSizePx);
    float footprint = 1e30;
    const ivec2 kSides[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int i = 0; i < 4; ++i) {
        ivec2 beside = g + kSides[i] * step;
        if (any(lessThan(beside, ivec2(0))) || any(greaterThanEqual(beside, size))) continue;
        vec4 besidePosition = texelFetch(uPosition, beside, 0);
        if (besidePosition.w >= 0.5) footprint = min(footprint, length(besidePosition.xyz - position));
    }
    return 1.0 / max(kPlaneFootprints * footprint, 1e-30);
}

// A tap's surface (its point and unit normal) weighed against the pixel's (n, position): the
// normal test times the off-plane distance's.
float weighSurface(vec3 qPosition, vec3 qNormal, vec3 n, vec3 position, float planeScale) {
    return weighNormals(dot(n, qNormal)) * exp(-abs(dot(n, qPosition - position)) * planeScale);
}

// A tap at G-buffer pixel q; 0 where q shows no surface.
float weighTap(ivec2 q, vec3 n, vec3 position, float planeScale) {
    vec4 qPosition = texelFetch(uPosition, q, 0);
    if (qPosition.w < 0.5) return 0.0;
    return weighSurface(qPosition.xyz, texelFetch(uNormal, q, 0).xyz, n, position, planeScale);
}

// The filter guide's encoding.
#include "../shared/filter_guide.h"

// A tap read from the guide; 0 where its buffer pixel shows no surface.
float weighGuide(vec4 guide, vec3 n, vec3 position, float planeScale) {
    if (guide.w == kGuideNoSurface) return 0.0;
    return weighSurface(guide.xyz, decodeGuideNormal(guide.w), n, position, planeScale);
}
