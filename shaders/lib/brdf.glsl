// Reflection models: Lambert plus normalised Phong around the mirror direction,
// rho_s (n + 2) / (2 pi) cos^n(alpha), split between the two by Schlick's Fresnel on materials
// with a specular part; written once in shared/surface_brdf.h for the photon roulette too.
#include "constants.glsl"
#include "../shared/surface_brdf.h"

vec3 evaluateBrdf(vec3 diffuse, vec4 specularExponent, vec3 n, vec3 wi, vec3 wo) {
    return evaluateSurfaceBrdf(diffuse, specularExponent, n, wi, wo);
}
