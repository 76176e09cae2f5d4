// Splat radius. density: the radius the density pass gave the photon. travel and path_density:
// computeTravelRadius (shared/photon_data.h), or none for a photon the density pass's travel cull
// found outside the view.
layout(std140, binding = kBindingPassParams) uniform SplatParamsBlock { SplatParams params; };

uint getRadiusMode() { return params.control.x; }

float computeSplatRadius(ResultPhoton photon) {
    uint mode = getRadiusMode();
    if (mode == kRadiusDensity) return photon.power.w;
    if (photon.power.w < 0.0) return 0.0; // kCulledPhoton
    return computeTravelRadius(photon.positionDistance.w, photon.normalDensity.w, params.radius, mode);
}
