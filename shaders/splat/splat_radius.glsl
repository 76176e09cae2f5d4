// Splat radius. travel (the thesis): grows linearly with the distance the photon travelled,
// from radius_min at dist_min to radius_max at dist_max. path_density (McGuire and Luebke 2009):
// the travel radius divided by the square root of the path density, so focused photons splat
// smaller, never below radius_min. density: the radius the density pass gave the photon.
layout(std140, binding = kBindingPassParams) uniform SplatParamsBlock { SplatParams params; };

uint getRadiusMode() { return params.control.x; }

float computeSplatRadius(ResultPhoton photon) {
    uint mode = getRadiusMode();
    if (mode == kRadiusDensity) return photon.power.w;
    float travelled = photon.positionDistance.w;
    float s = clamp((travelled - params.radius.z) / max(params.radius.w - params.radius.z, 1e-9), 0.0, 1.0);
    float r = mix(params.radius.x, params.radius.y, s);
    if (mode == kRadiusPathDensity) r = max(params.radius.x, r / sqrt(max(photon.normalDensity.w, 1.0)));
    return r;
}
