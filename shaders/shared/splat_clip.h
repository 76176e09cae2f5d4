// Splats clipped where the photon's surface meets another: the density pass casts four short rays
// in the photon's surface plane, along the axes of the splat basis, and keeps how far each got
// (at most the radius). The splat draws only the part of its disc inside those four lines, so it
// neither leaks through a thin wall nor climbs a corner, and divides each pixel's share by the
// kernel mass that the pixel's own disc keeps inside the lines (splat.frag).
#ifndef ISPM_SPLAT_CLIP_H
#define ISPM_SPLAT_CLIP_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// Per result photon: distances (m) free of obstacles along +t, -t, +b, -b (buildSplatBasis).
ISPM_CONST int kBindingSplatClip = 18;

// A kept mass below this is taken as this: a pixel in a slot narrower than the disc keeps a
// finite weight (it may then lose some light).
ISPM_CONST float kMinKeptMass = 0.25f;

// The in-plane basis of a splat: built from the world axis least aligned with n, so that on the
// axis-aligned walls of box scenes t and b follow the walls and a clip line is exactly a wall.
ISPM_INLINE void buildSplatBasis(vec3 n, ISPM_OUT(vec3) t, ISPM_OUT(vec3) b) {
    vec3 a = abs(n);
    vec3 axis = a.x <= a.y && a.x <= a.z ? vec3(1.0f, 0.0f, 0.0f)
                                          : (a.y <= a.z ? vec3(0.0f, 1.0f, 0.0f) : vec3(0.0f, 0.0f, 1.0f));
    t = normalize(cross(n, axis));
    b = cross(n, t);
}

// Mass of the splat kernel 2 / (pi r^2) (1 - s^2 / r^2) beyond a chord at distance u r from the
// centre (u in [0, 1]): (8 / (3 pi)) times the integral of (1 - x^2)^(3/2) from u to 1.
ISPM_INLINE float computeKernelMassBeyond(float u) {
    const float kPi = 3.14159265358979f;
    u = clamp(u, 0.0f, 1.0f);
    float w = sqrt(max(0.0f, 1.0f - u * u));
    float integral = 3.0f * kPi / 16.0f -
                     (0.25f * u * w * w * w + 0.375f * u * w + 0.375f * asin(u));
    return max(0.0f, 8.0f / (3.0f * kPi) * integral);
}

// Kernel mass inside the four clip lines (the corners two lines cut off together are small and
// counted twice; the floor keeps the result positive).
ISPM_INLINE float computeKeptMass(vec4 clipM, float radiusM) {
    float lost = computeKernelMassBeyond(clipM.x / radiusM) + computeKernelMassBeyond(clipM.y / radiusM) +
                 computeKernelMassBeyond(clipM.z / radiusM) + computeKernelMassBeyond(clipM.w / radiusM);
    return max(1.0f - lost, kMinKeptMass);
}

ISPM_NAMESPACE_END

#endif
