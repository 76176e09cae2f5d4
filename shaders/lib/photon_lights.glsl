// Which light a photon came from, and the per-light counters reports read
// (shared/photon_data.h).
#include "../shared/photon_data.h"

layout(std430, binding = kBindingEmissionGrids) readonly buffer EmissionGrids { uvec4 emissionGrids[]; };
layout(std430, binding = kBindingLightCounts) buffer LightCounts { LightPhotonCounters lightCounts[]; };

// The light that emitted photon `id`: the grids (x = first photon, y = view, z = light, or
// emitter group after the lights) are in photon order.
uint findPhotonLight(uint id) {
    uint light = 0u;
    for (uint g = 0u; g < uint(emissionGrids.length()); ++g) {
        if (emissionGrids[g].x <= id) light = emissionGrids[g].z;
    }
    return light;
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
