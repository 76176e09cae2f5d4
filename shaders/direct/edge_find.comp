// Edges of the direct light: lists each pixel whose footprint likely holds more than one light,
// for edge_shade.comp to average over the pixel's area. A pixel is listed when, against one of
// its eight neighbours, it shows a surface where the other shows the background; or another
// instance or a surface turned by more than kDirectEdgeCos, and a direct light that differs by
// more than kDirectEdgeContrast of the brighter (dark creases stay out); or when its light (the
// direct light over the surface's reflectance, so a texture's texels are no edge) bends: along
// one of the four lines through the pixel, the neighbours' mean differs from the pixel's by more
// than kDirectEdgeContrast of the brightest (a shadow's or a spot cone's edge; a smooth gradient
// does not bend). Each listed pixel carries how many times edge_shade.comp halves its samples, by
// its need (shared/scene_data.h). Counts edge_shade.comp's work groups as it lists: one for every
// kDirectEdgePixelsPerGroup-th pixel. With EDGE_EMISSION 1 (a scene with an emitter) the
// emission a pixel shows adds to its light.
#ifndef EDGE_EMISSION
#define EDGE_EMISSION 0
#endif
#include "lib/frame_constants.glsl"

#include "lib/viewer_gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = kUnitDirect) uniform sampler2D uDirect;
layout(std430, binding = kBindingDirectEdges) buffer DirectEdges {
    DirectEdgeHeader header;
    uint edgePixels[];
};

const float kMinReflectance = 1e-3; // a black surface's light: its radiance x 1000

struct Shown {
    float instance; // + 1; 0: the background
    vec3 normal;
    vec3 radiance; // the direct light
    vec3 light;    // the direct light over the reflectance
};

Shown getShown(ivec2 pixel) {
    Shown s;
    s.instance = texelFetch(uPosition, pixel, 0).w;
    s.normal = texelFetch(uNormal, pixel, 0).xyz;
    s.radiance = s.instance > 0.5 ? texelFetch(uDirect, pixel, 0).rgb : vec3(0.0);
#if EDGE_EMISSION
    // What an emitter shows counts as its light: a lamp's outline is an edge like a shadow's.
    s.radiance += texelFetch(uEmission, pixel, 0).rgb;
#endif
    s.light = s.radiance / max(texelFetch(uDiffuse, pixel, 0).rgb, vec3(kMinReflectance));
    return s;
}

bool differs(vec3 a, vec3 b) {
    return any(greaterThan(abs(a - b), kDirectEdgeContrast * max(a, b)));
}

bool isEdgeWith(Shown a, Shown b) {
    if ((a.instance > 0.5) != (b.instance > 0.5)) return true;
    bool otherSurface = abs(a.instance - b.instance) > 0.5 || dot(a.normal, b.normal) < kDirectEdgeCos;
    return otherSurface && differs(a.radiance, b.radiance);
}

bool bends(vec3 before, vec3 centre, vec3 after) {
    vec3 brightest = max(max(before, after), centre);
    return any(greaterThan(abs(before + after - 2.0 * centre), kDirectEdgeContrast * brightest));
}

// The light a pixel shows: the direct light on a surface, the background's radiance elsewhere.
vec3 getShownRadiance(Shown s) {
    return s.instance > 0.5 ? s.radiance : frame.backgroundRadiance;
}

// How many times a listed pixel halves its samples, by how far the light spreads from `lowest`
// to `highest` over it and its eight neighbours against its own (kDirectEdgeFullNeed).
uint computeHalvings(vec3 own, vec3 lowest, vec3 highest) {
    vec3 spread = (highest - lowest) / sqrt(own * own + kDirectEdgeNeedEpsilon);
    float need = max(spread.x, max(spread.y, spread.z));
    return need >= kDirectEdgeFullNeed ? 0u : (need >= kDirectEdgeHalfNeed ? 1u : 2u);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(uDirect, 0);
    if (any(greaterThanEqual(pixel, size))) return;
    Shown centre = getShown(pixel);
    vec3 own = getShownRadiance(centre);
    vec3 lowest = own;
    vec3 highest = own;
    bool edge = false;
    const ivec2 kLines[4] = ivec2[4](ivec2(1, 0), ivec2(0, 1), ivec2(1, 1), ivec2(1, -1));
    for (int i = 0; i < 4; ++i) {
        Shown before = getShown(clamp(pixel - kLines[i], ivec2(0), size - 1));
        Shown after = getShown(clamp(pixel + kLines[i], ivec2(0), size - 1));
        lowest = min(lowest, min(getShownRadiance(before), getShownRadiance(after)));
        highest = max(highest, max(getShownRadiance(before), getShownRadiance(after)));
        edge = edge || isEdgeWith(centre, before) || isEdgeWith(centre, after) ||
               (centre.instance > 0.5 && bends(before.light, centre.light, after.light));
    }
    if (!edge) return;
    uint halvings = computeHalvings(own, lowest, highest);
    uint index = atomicAdd(header.pixels, 1u);
    edgePixels[index] = (uint(pixel.y) * uint(size.x) + uint(pixel.x)) | (halvings << kDirectEdgeHalvingShift);
    if (index % kDirectEdgePixelsPerGroup == 0u) atomicAdd(header.groupsX, 1u);
}
