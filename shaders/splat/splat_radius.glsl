// Splat radius. travel (the thesis): grows linearly with the distance the photon travelled,
// from radius_min at dist_min to radius_max at dist_max. path_density (McGuire and Luebke 2009):
// the travel radius divided by the square root of the path density, so focused photons splat
// smaller, never below radius_min. density: the radius the density pass gave the photon.
layout(location = 1) uniform vec4 uRadius;     // x = radius_min, y = radius_max, z = dist_min, w = dist_max
layout(location = 2) uniform float uSquash; // thickness along the normal / radius
layout(location = 4) uniform uvec2 uSplatModes; // x = radius mode (kRadius*), y = 1: front faces
                                                // are dropped in the fragment stage (splat_faces all)

uint getRadiusMode() { return uSplatModes.x; }

float computeSplatRadius(ResultPhoton photon) {
    uint mode = getRadiusMode();
    if (mode == kRadiusDensity) return photon.power.w;
    float travelled = photon.positionDistance.w;
    float s = clamp((travelled - uRadius.z) / max(uRadius.w - uRadius.z, 1e-9), 0.0, 1.0);
    float r = mix(uRadius.x, uRadius.y, s);
    if (mode == kRadiusPathDensity) r = max(uRadius.x, r / sqrt(max(photon.normalDensity.w, 1.0)));
    return r;
}
