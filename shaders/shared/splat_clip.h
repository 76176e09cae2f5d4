// Splats clipped where the photon's surface meets another: the density pass casts kClipRays short
// rays in the photon's surface plane (evenly around it, the first along the splat basis's t) and
// keeps, for each that hit a surface within the radius, the line where that surface cuts the
// plane. The splat draws only the pixels on the photon's side of every line, so it neither leaks
// through a thin wall, nor climbs a corner; a line whose surface ends inside the disc (a
// building's outer corner, a wall's free end) cuts only the wedge behind the surface
// (findLineWedges), and the splat
// divides each pixel's share by the kernel mass that the pixel's own disc keeps inside the
// lines (splat.frag), so a uniform irradiance stays uniform up to a wall.
#ifndef ISPM_SPLAT_CLIP_H
#define ISPM_SPLAT_CLIP_H

#include "host_device.h"
#include "photon_scatter.h"

ISPM_NAMESPACE_BEGIN

// Per result photon kClipVec4s vec4s: kClipRays / 2 with two lines each, then the box extents
// along +t, -t, +b, -b (m), then kClipRays / 4 with each line's wedge (findLineWedges) in its
// lanes, as a float holding the integer. A line is its pole: the point of the line nearest the
// photon, in the plane's (t, b) coordinates (m); the photon's side is { x : dot(x, pole) <
// dot(pole, pole) }. (0, 0): no line (the ray hit nothing, or a wall another ray had found).
ISPM_CONST int kBindingSplatClip = 18;
ISPM_CONST uint kClipRays = 8u; // photon_density.comp holds them in the lanes of two vec4s
ISPM_CONST uint kClipVec4s = kClipRays / 2u + 1u + kClipRays / 4u;
// A line's wedge: the directions from the photon, seen from which the surface stands on the line
// (a wall's span), as two codes: the bound on the side counterclockwise of the pole (low byte) and
// on the clockwise side (next byte), each a direction getWedgeDirection gives or kWedgeOpen, the
// surface running on past the disc that way.
ISPM_CONST uint kWedgeOpen = 2u * kClipRays;
ISPM_CONST uint kWedgeOpenBoth = kWedgeOpen | (kWedgeOpen << 8u);

// A kept mass below this is taken as this: a pixel in a slot narrower than the disc keeps a
// finite weight (it may then lose some light), and the few photons a pixel deep in a corner
// gathers are not multiplied by more than 1 / kMinKeptMass. Eight seeds at 256x256 (rel RMSE
// 4x4, worst seed and median energy; Cornell box / courtyard outside / room): 0.25 gave 0.123 /
// 0.251 / 0.255 and 0.986 / 0.987 / 0.992, 0.33 gives 0.123 / 0.245 / 0.238 and 0.985 / 0.973 /
// 0.980, 0.4 0.122 / 0.249 / 0.234 and 0.984 / 0.964 / 0.972, 0.1 0.124 / 0.351 / 0.399.
ISPM_CONST float kMinKeptMass = 0.33f;
// Two poles closer than this fraction of the radius are one wall (several rays hit it).
ISPM_CONST float kSameLineFraction = 0.02f;

// The in-plane basis of a splat: built from the world axis least aligned with n, so that on the
// axis-aligned walls of box scenes t and b follow the walls.
ISPM_INLINE void buildSplatBasis(vec3 n, ISPM_OUT(vec3) t, ISPM_OUT(vec3) b) {
    vec3 a = abs(n);
    vec3 axis = a.x <= a.y && a.x <= a.z
                    ? vec3(1.0f, 0.0f, 0.0f)
                    : (a.y <= a.z ? vec3(0.0f, 1.0f, 0.0f) : vec3(0.0f, 0.0f, 1.0f));
    t = normalize(cross(n, axis));
    b = cross(n, t);
}

// Direction of clip ray i in the plane's (t, b) coordinates.
ISPM_INLINE vec2 getClipDirection(uint i) {
    const float kStep = kTwoPiF / float(kClipRays);
    return vec2(cos(kStep * float(i)), sin(kStep * float(i)));
}

// The pole of the line where a surface with in-plane normal component `normal2` (any length,
// either sign), hit at in-plane offset `hit2`, cuts the plane. A surface almost parallel to the
// plane (a step's top) gives a line across the ray instead.
ISPM_INLINE vec2 computeClipPole(vec2 hit2, vec2 normal2, vec2 ray2) {
    const float kParallel = 0.1f; // |in-plane normal| below this: nearly parallel
    vec2 n = dot(normal2, normal2) > kParallel * kParallel ? normalize(normal2) : ray2;
    float c = dot(hit2, n);
    if (c < 0.0f) {
        n = -n;
        c = -c;
    }
    return n * c;
}

// Mass of the splat kernel 2 / (pi r^2) (1 - s^2 / r^2) beyond a chord at distance u r from the
// centre (u in [0, 1]): (8 / (3 pi)) times the integral of (1 - x^2)^(3/2) from u to 1. The
// splat evaluates it per pixel, so a least-squares fit in v = 1 - u replaces the closed form
// (which needs asin): v^(5/2) (0.96212 - 0.52210 v + 0.05995 v^2), off by at most 4e-5.
ISPM_INLINE float computeKernelMassBeyond(float u) {
    float v = 1.0f - clamp(u, 0.0f, 1.0f);
    return v * v * sqrt(v) * (0.96212f + v * (-0.52210f + v * 0.05995f));
}

// Whether in-plane offset x lies beyond the line of `pole` (none: a zero pole).
ISPM_INLINE bool isBeyondLine(vec2 x, vec2 pole) {
    float p2 = dot(pole, pole);
    return p2 > 0.0f && dot(x, pole) > p2;
}

// Zeroes every pole that repeats an earlier one: a wall several rays hit is one line.
ISPM_INLINE void removeRepeatedLines(ISPM_INOUT_ARRAY(vec2, poles, kClipRays), float radiusM) {
    float same2 = kSameLineFraction * kSameLineFraction * radiusM * radiusM;
    for (uint i = 1u; i < kClipRays; ++i) {
        for (uint j = 0u; j < i; ++j) {
            vec2 d = poles[j] - poles[i];
            if (dot(poles[j], poles[j]) > 0.0f && dot(d, d) < same2) poles[i] = vec2(0.0f);
        }
    }
}

// Direction of wedge bound `code` in the plane's (t, b) coordinates: the clip rays' directions
// (even codes) and the bisectors between neighbouring rays (odd codes).
// The splat's fragment stage calls it per covered pixel: cosines from a table (codes step 22.5
// degrees, kClipRays being 8), turned by the quadrant.
ISPM_INLINE vec2 getWedgeDirection(uint code) {
    const float kCos[5] = {1.0f, 0.92387953f, 0.70710678f, 0.38268343f, 0.0f};
    uint step = code % 4u;
    vec2 d = vec2(kCos[step], kCos[4u - step]);
    uint quadrant = (code / 4u) % 4u;
    return quadrant == 0u
               ? d
               : (quadrant == 1u ? vec2(-d.y, d.x) : (quadrant == 2u ? -d : vec2(d.y, -d.x)));
}

// The bound between clip ray `met` (the outermost that met a line on its side) and its neighbour
// `passed` (the next one out, which crossed the line without meeting anything there).
ISPM_INLINE uint computeWedgeBound(uint met, uint passed) {
    bool after = passed == (met + 1u) % kClipRays; // counterclockwise of `met`
    return (2u * met + (after ? 1u : 2u * kClipRays - 1u)) % (2u * kClipRays);
}

// Each line's wedge (kWedgeOpenBoth where none, or a zero pole): the clip rays that cross the
// line within the radius, taken by where along the line they cross it, either meet it or pass
// it (`hitsM`: each ray's distance to what it met, the radius when nothing). Where one passes
// beyond the outermost that met it, the surface ends between the two neighbouring rays (a
// wall's free end, a building's outer corner): the wedge's bound on that side is their bisector,
// and the disc reaches round the end while the line still cuts it behind the surface (without
// the bound a line would cut open ground off the disc; without the line light would leak
// through the wall into the room behind it). A door in a wall does not bound it: the rays
// through the door lie between rays that meet the wall.
ISPM_INLINE void findLineWedges(const vec2 poles[kClipRays], const float hitsM[kClipRays],
                                float radiusM, ISPM_OUT_ARRAY(uint, wedges, kClipRays)) {
    // Past the crossing by more than this share of it (and of the radius): not the same surface
    // (a slanted wall's line, met by rays above and beneath the plane, differs by round-off).
    const float kPassed = 0.05f;
    const float kNone = 4.0f * radiusM; // beyond any crossing within the radius
    for (uint i = 0u; i < kClipRays; ++i) {
        wedges[i] = kWedgeOpenBoth;
        float p2 = dot(poles[i], poles[i]);
        if (p2 <= 0.0f) continue;
        vec2 along = vec2(-poles[i].y, poles[i].x); // counterclockwise of the pole
        // Where each ray crosses the line, along it (times |pole|, counterclockwise positive;
        // kNone: not within the radius), whether it met the line there, and the rays that met it
        // farthest out each way.
        float atM[kClipRays];
        bool meets[kClipRays];
        float highM = -kNone;
        float lowM = kNone;
        uint high = kClipRays;
        uint low = kClipRays;
        for (uint j = 0u; j < kClipRays; ++j) {
            vec2 ray2 = getClipDirection(j);
            float toward = dot(ray2, poles[i]);
            float crossingM = toward > 0.0f ? p2 / toward : radiusM;
            atM[j] = crossingM < radiusM ? dot(ray2, along) * crossingM : kNone;
            meets[j] = atM[j] != kNone && hitsM[j] <= crossingM + kPassed * (crossingM + radiusM);
            if (!meets[j]) continue;
            if (atM[j] > highM) {
                highM = atM[j];
                high = j;
            }
            if (atM[j] < lowM) {
                lowM = atM[j];
                low = j;
            }
        }
        if (high == kClipRays) continue; // round-off: no ray met its own line
        // The nearest crossing rays beyond those, which passed the line: where it ends. The
        // crossing rays are neighbours in angle, so each end lies between neighbouring rays.
        float endHighM = kNone;
        float endLowM = -kNone;
        uint endHigh = kClipRays;
        uint endLow = kClipRays;
        for (uint j = 0u; j < kClipRays; ++j) {
            if (atM[j] == kNone || meets[j]) continue;
            if (atM[j] > highM && atM[j] < endHighM) {
                endHighM = atM[j];
                endHigh = j;
            }
            if (atM[j] < lowM && atM[j] > endLowM) {
                endLowM = atM[j];
                endLow = j;
            }
        }
        uint ccw = endHigh < kClipRays ? computeWedgeBound(high, endHigh) : kWedgeOpen;
        uint cw = endLow < kClipRays ? computeWedgeBound(low, endLow) : kWedgeOpen;
        wedges[i] = ccw | (cw << 8u);
    }
}

// Whether in-plane offset x (beyond the line of `pole`, or on it) lies in the line's wedge.
ISPM_INLINE bool isInWedge(vec2 x, uint wedge) {
    uint ccw = wedge & 0xffu;
    uint cw = wedge >> 8u;
    if (ccw != kWedgeOpen) {
        vec2 d = getWedgeDirection(ccw);
        if (x.x * d.y - x.y * d.x < 0.0f) return false; // counterclockwise of the bound
    }
    if (cw != kWedgeOpen) {
        vec2 d = getWedgeDirection(cw);
        if (d.x * x.y - d.y * x.x < 0.0f) return false; // clockwise of the bound
    }
    return true;
}

// How far the box around a disc of radius r reaches along +t, -t, +b, -b: up to a line across
// that axis (a box scene's wall) that runs past the disc both ways, else r.
ISPM_INLINE vec4 computeClipExtent(const vec2 poles[kClipRays], const uint wedges[kClipRays],
                                   float radiusM) {
    const float kAlong = 0.999f; // a line across an axis, not a slanted one
    vec4 extent = vec4(radiusM);
    for (uint i = 0u; i < kClipRays; ++i) {
        float c = length(poles[i]);
        if (c <= 0.0f || wedges[i] != kWedgeOpenBoth) continue;
        vec2 axis = poles[i] / c;
        if (axis.x > kAlong) extent.x = min(extent.x, c);
        if (-axis.x > kAlong) extent.y = min(extent.y, c);
        if (axis.y > kAlong) extent.z = min(extent.z, c);
        if (-axis.y > kAlong) extent.w = min(extent.w, c);
    }
    return extent;
}

// Kernel mass that the disc of radius r around in-plane offset x loses beyond the line of a
// nonzero pole.
ISPM_INLINE float computeMassBeyondLine(vec2 x, vec2 pole, float radiusM) {
    float p2 = dot(pole, pole);
    float toLine = (p2 - dot(x, pole)) / sqrt(p2);
    return computeKernelMassBeyond(toLine / radiusM);
}

// Kernel mass that the disc of radius r around in-plane offset x keeps on the photon's side of
// the first `lines` poles, distinct lines all nonzero, the first `wholeLines` of them running
// past the disc both ways (kWedgeOpenBoth) and the rest with their wedges (removeRepeatedLines,
// then packed as loadSplatShape does; the corners two walls cut off together are counted twice,
// and the floor keeps the result positive); -1 when x itself lies beyond one of them, in its
// wedge. A bounded line counts where x's nearest point on it lies in its wedge; beyond it outside
// its wedge (round a wall's end) x loses nothing to it. The splat's fragment stage runs it per
// covered pixel, so the whole lines take the short loop (llvmpipe runs a branch's both sides).
ISPM_INLINE float computeKeptMass(vec2 x, const vec2 poles[kClipRays], const uint wedges[kClipRays],
                                  uint wholeLines, uint lines, float radiusM) {
    float lost = 0.0f;
    for (uint i = 0u; i < wholeLines; ++i) {
        if (isBeyondLine(x, poles[i])) return -1.0f;
        lost += computeMassBeyondLine(x, poles[i], radiusM);
    }
    for (uint i = wholeLines; i < lines; ++i) {
        float p2 = dot(poles[i], poles[i]);
        float beyond = dot(x, poles[i]) - p2;
        if (beyond > 0.0f) {
            if (isInWedge(x, wedges[i])) return -1.0f;
        } else if (isInWedge(x - poles[i] * (beyond / p2), wedges[i])) {
            lost += computeMassBeyondLine(x, poles[i], radiusM);
        }
    }
    return max(1.0f - lost, kMinKeptMass);
}

ISPM_NAMESPACE_END

#endif
