// Emissive triangles as lights (docs/design.md "Emitters"), shared by C++ and GLSL: the table of
// every emitting triangle in world space that direct light, the path tracer and the photon
// emission sample by power, and the parameters of the photon emission from them.
#ifndef ISPM_EMITTER_DATA_H
#define ISPM_EMITTER_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// One emitting triangle, world space (GpuScene re-makes the table when instances move). A
// triangle is picked with probability weight / total weight, its weight being the power it
// sends out, mean(radiance) x area x pi x sides (FrameConstants::emitterWeight holds the total):
// so a picked point has the area density mean(radiance) x pi x sides / total, the same for every
// point of every emitter of the same material, which lets a ray that hits an emitter find the
// pdf light sampling would have given it (MIS) from the material alone.
struct GpuEmitter {
    vec4 p0Cdf;      // xyz vertex 0; w = the cumulative pick probability through this triangle
    vec4 edge1Area;  // xyz vertex 1 - vertex 0; w = area (m^2)
    vec4 edge2Group; // xyz vertex 2 - vertex 0; w = its group (uint bits): the emissive material
                     // whose photons it emits (PhotonEmitPass)
    vec4 radiance;   // rgb W/(m^2 sr) on the side the winding faces; w = 1: both sides emit
};
ISPM_STATIC_ASSERT_SIZE(GpuEmitter, 64);

ISPM_CONST int kBindingEmitters = 36; // GpuEmitter, in pick order

// The sides of an emitter that emit (1 or 2), from GpuMaterial::emission.w / radiance.w.
ISPM_INLINE float getEmitterSides(float twoSided) {
    return twoSided > 0.5f ? 2.0f : 1.0f;
}

// The sampling weight per square metre of an emitter of `radiance` (W/(m^2 sr)), before
// dividing by the total: the power it sends out of each side per m^2, mean over channels.
ISPM_INLINE float computeEmitterWeightPerArea(vec3 radiance, float twoSided) {
    return (radiance.x + radiance.y + radiance.z) * (3.14159265358979f / 3.0f) *
           getEmitterSides(twoSided);
}

// Photon emission from the emitters of one group (shaders/photon/emitter_emit.comp, std140 at
// kBindingPassParams): `photons` photons from triangles [firstEmitter, firstEmitter + count),
// picked by power within the group (stratified: photon i's number in [i, i + 1) / photons), each
// leaving a uniform point of its triangle in a cosine-weighted direction with the group's power
// / photons, its first hit found through the BVH.
struct EmitterEmitParams {
    uint firstEmitter; // the group's first triangle in the table
    uint emitterCount;
    uint firstPhoton; // global index of its first photon (after every light view's grid)
    uint photons;
    uint light;          // the index its photons count under (lights, then emitter groups)
    uint seed;           // the frame's
    uint rngGenerator;   // kRngPcg or kRngLcg
    uint firstBounce;    // kFirstBounce*
    float rayOffsetM;    // ray offset off the emitter (GpuScene::getRayEpsilon)
    float groupWeight;   // the group's power, the sum of its triangles' weights (W)
    uint bounceCapacity; // bounce photons the buffer holds
    uint padding0;
};
ISPM_STATIC_ASSERT_SIZE(EmitterEmitParams, 48);

ISPM_CONST uint kEmitterEmitGroupSize = 64u;

ISPM_NAMESPACE_END

#endif
