// glTF's photometric lights and metallic-roughness materials in ispm's terms: candela and lux to
// W/sr and W/m^2, and base colour, metallic and roughness to diffuse + Phong. Written once here so
// the importer, the documentation (docs/scene-format.md, "glTF") and the tests agree.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <algorithm>

namespace ispm {

// Luminous efficacy at 555 nm, lm/W: the SI definition of the candela. Blender's glTF exporter
// (lighting mode "Standard") multiplies watts by it, so dividing gives its watts back.
inline constexpr float kLumensPerWatt = 683.0f;

// Point and spot lights: luminous intensity (cd = lm/sr) to radiant intensity (W/sr).
inline glm::vec3 convertCandelaToWattsPerSr(glm::vec3 candela) {
    return candela / kLumensPerWatt;
}

// Directional lights: illuminance (lux = lm/m^2) to irradiance (W/m^2).
inline glm::vec3 convertLuxToWattsPerM2(glm::vec3 lux) {
    return lux / kLumensPerWatt;
}

// Reflectance of a dielectric at normal incidence (index of refraction 1.5), glTF's value.
inline constexpr float kDielectricF0 = 0.04f;
// Phong exponents for roughness 0 (a mirror in all but name) and above: the tracer stores no
// photons on lobes narrower than 1000 (photon_trace.comp), so 1e4 is a mirror to it.
inline constexpr float kMaxGltfPhongExponent = 1e4f;
// And for roughness 1 and near it, where the formula gives 0 or less: pow(0, 0) is undefined in
// GLSL, so the widest lobe is cos^1.
inline constexpr float kMinGltfPhongExponent = 1.0f;

// Roughness r (perceptual, glTF) to a Phong exponent about the mirror direction: alpha = r^2,
// Blinn-Phong's n = 2 / alpha^2 - 2 matches a Beckmann lobe of width alpha, and a lobe about the
// mirror direction is twice as wide in angle as one about the half vector, so n / 4.
inline float convertRoughnessToPhongExponent(float roughness) {
    const float alpha = std::max(roughness * roughness, 1e-4f); // r = 0: the cap below
    const float blinn = 2.0f / (alpha * alpha) - 2.0f;
    constexpr float kHalfVectorToMirror = 0.25f;
    return std::clamp(blinn * kHalfVectorToMirror, kMinGltfPhongExponent, kMaxGltfPhongExponent);
}

// The metallic-roughness model as diffuse + Phong: a dielectric part (1 - metallic) with
// Lambertian base colour under a colourless F0 coat, and a metal part whose Phong lobe takes the
// base colour. `textureMean` is the base colour texture's mean (linear; 1 without one): the
// diffuse term is multiplied by the texture per point, the metal's specular by its mean.
// diffuse + specular <= 1 per channel for base colours in [0, 1].
inline Material convertMetallicRoughness(glm::vec3 baseColor, float metallic, float roughness,
                                         glm::vec3 textureMean) {
    Material m;
    const float dielectric = 1.0f - metallic;
    m.diffuse = dielectric * (1.0f - kDielectricF0) * baseColor;
    m.specular = glm::vec3(dielectric * kDielectricF0) + metallic * baseColor * textureMean;
    m.phongExponent = convertRoughnessToPhongExponent(roughness);
    return m;
}

} // namespace ispm
