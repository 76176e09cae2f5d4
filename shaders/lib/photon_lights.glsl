// Which light a photon came from, and the per-light counters reports read
// (shared/photon_data.h). Needs scene_buffers.glsl (lightViews) included before.
#include "../shared/photon_data.h"

layout(std430, binding = kBindingEmissionGrids) readonly buffer EmissionGrids { uvec4 emissionGrids[]; };
layout(std430, binding = kBindingLightCounts) buffer LightCounts { LightPhotonCounters lightCounts[]; };

// The light that emitted photon `id`: the grids (x = first photon, y = view) are in photon order.
uint findPhotonLight(uint id) {
    uint view = 0u;
    for (uint g = 0u; g < uint(emissionGrids.length()); ++g) {
        if (emissionGrids[g].x <= id) view = emissionGrids[g].y;
    }
    return lightViews[view].info.x;
}

// Adds one to component `which` (0 bounced, 1 stored, 2 in view) of `light`'s counters; a light
// the counters do not hold (photons a test made by hand) is not counted.
void countPhoton(uint light, int which) {
    if (light < uint(lightCounts.length())) atomicAdd(lightCounts[light].counts[which], 1u);
}

// ResultPhoton.incoming.w: reflections in the low bits, the light above.
float packReflectionsLight(uint reflections, uint light) {
    return uintBitsToFloat(reflections | (light << kReflectionBits));
}
uint unpackLight(float bits) { return floatBitsToUint(bits) >> kReflectionBits; }
