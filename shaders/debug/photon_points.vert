// Photons as points over the scene: bounce photons (where the first bounce left them) or result
// photons (where they landed), coloured by kind, by direction or by power (PhotonPointsParams).
#include "lib/frame_constants.glsl"
#include "shared/photon_data.h"
#include "shared/scene_data.h"
#include "shared/debug_data.h"

layout(std430, binding = kBindingPhotonCounters) readonly buffer Counters { PhotonCounters counters; };

#ifdef RESULT_PHOTONS
layout(std430, binding = kBindingResultPhotons) readonly buffer Photons { ResultPhoton photons[]; };
uint getPhotonCount() { return min(counters.result.x, counters.result.y); }
vec3 getDirection(uint i) { return photons[i].incoming.xyz; } // of travel, onto the surface
#else
uint getPhotonCount() { return counters.bounce.x; }
layout(std430, binding = kBindingBouncePhotons) readonly buffer Photons { BouncePhoton photons[]; };
vec3 getDirection(uint i) { return photons[i].directionDensity.xyz; } // leaving the surface
#endif

layout(std140, binding = kBindingPassParams) uniform PhotonPointsParamsBlock { PhotonPointsParams params; };

out vec3 vColor;
out vec3 vPositionW;

const float kTintWeight = 0.5; // half kind (which buffer), half the photon's own hue
const float kTinyPower = 1e-30; // keeps black photons from dividing by zero

void main() {
    // The draw covers the buffer's capacity; the count of this frame stays on the GPU.
    if (uint(gl_VertexID) >= getPhotonCount()) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume: dropped
        gl_PointSize = 1.0;
        vColor = vec3(0.0);
        vPositionW = vec3(0.0);
        return;
    }
    vec3 positionW = photons[gl_VertexID].positionDistance.xyz;
    vec3 power = photons[gl_VertexID].power.rgb;
    vPositionW = positionW;
    gl_Position = frame.clipFromWorld * vec4(positionW, 1.0);
    gl_PointSize = params.pointSizePx;
    if (params.colouring == kPhotonColourDirection) {
        vColor = getDirection(uint(gl_VertexID)) * 0.5 + 0.5;
    } else if (params.colouring == kPhotonColourPower) {
        vColor = pow(clamp(power * params.powerScale, 0.0, 1.0), vec3(params.inverseGamma));
    } else {
        float peak = max(max(power.r, power.g), max(power.b, kTinyPower));
        vColor = mix(power / peak, params.tint, kTintWeight);
    }
}
