// glTF metallic-roughness materials, their base colour images, and KHR_lights_punctual lights, in
// ispm's terms (gltf_units.h). Values outside glTF's ranges are input errors with their JSON path.
#include "scene/gltf_materials.h"

#include "core/strings.h"
#include "scene/gltf_units.h"
#include "scene/scene_parse.h"
#include "scene/scene_texture.h"

#include <cmath>
#include <numbers>

namespace ispm {

namespace {

constexpr double kMaxLightPower = 1e12; // W/sr or W/m^2, as scene files' lights
// A spot's light camera sees twice its outer angle; 90 degrees degenerates the projection, so
// glTF's widest spot (pi/2) is narrowed to this, as scene files' spots are bounded.
constexpr float kMaxSpotHalfAngleDeg = 89.9f;
// glTF's alpha test for alphaMode BLEND, which ispm cannot draw partly transparent.
constexpr double kBlendAlphaCutoff = 0.5;
// A cutoff on the texture's alpha that no texel passes (alpha is at most 1): the whole material
// is cut out, as glTF's would be with its factor's alpha below the cutoff.
constexpr double kNothingPasses = 2.0;
// normalTexture.scale beyond this tilts every texel's normal to the surface's plane (x and y
// outweigh z a hundredfold): a typing slip rather than a wish.
constexpr double kMaxNormalScale = 100.0;

double readUnit(const GltfFile& file, double value, const std::string& path) {
    if (!(value >= 0.0 && value <= 1.0)) {
        file.fail(path, strCat("a number in [0, 1], got ", value));
    }
    return value;
}

glm::vec3 readUnitColor(const GltfFile& file, const std::vector<double>& values, size_t size,
                        const std::string& path) {
    if (values.size() != size) file.fail(path, strCat(size, " numbers in [0, 1]"));
    glm::vec3 c;
    for (int i = 0; i < 3; ++i)
        c[i] = float(readUnit(file, values[static_cast<size_t>(i)], strCat(path, "/", i)));
    return c;
}

// The scene texture of glTF texture `index` (its image, converted once).
uint32_t importTexture(const GltfFile& file, int index, const std::string& path,
                       std::vector<uint32_t>& imageTextures, Scene& scene) {
    const tinygltf::Model& model = file.model;
    if (index < 0 || static_cast<size_t>(index) >= model.textures.size()) {
        file.fail(path, strCat("a texture index below ", model.textures.size(), ", got ", index));
    }
    const int source = model.textures[static_cast<size_t>(index)].source;
    if (source < 0 || static_cast<size_t>(source) >= model.images.size()) {
        file.fail(strCat("/textures/", index, "/source"), "an image index");
    }
    const auto image = static_cast<size_t>(source);
    if (imageTextures[image] != kNoTexture) return imageTextures[image];
    const tinygltf::Image& in = model.images[image];
    SceneTexture texture;
    texture.name = in.name.empty() ? strCat("image_", image) : in.name;
    if (!convertToRgba8(in.image.data(), in.width, in.height, in.component, in.bits, texture) ||
        in.image.size() < static_cast<size_t>(in.width) * static_cast<size_t>(in.height) *
                              static_cast<size_t>(in.component) *
                              static_cast<size_t>(in.bits / 8)) {
        file.fail(strCat("/images/", image), "a decodable PNG or JPEG image of 8 or 16 bits");
    }
    imageTextures[image] = static_cast<uint32_t>(scene.textures.size());
    scene.textures.push_back(std::move(texture));
    return imageTextures[image];
}

float readExtensionNumber(const GltfFile& file, const tinygltf::ExtensionMap& extensions,
                          const char* extension, const char* key, float fallback,
                          const std::string& path) {
    const auto it = extensions.find(extension);
    if (it == extensions.end() || !it->second.Has(key)) return fallback;
    const tinygltf::Value& v = it->second.Get(key);
    const double value = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(value >= 0.0 && value <= kMaxLightPower)) {
        file.fail(strCat(path, "/extensions/", extension, "/", key), "a number >= 0");
    }
    return float(value);
}

// The material's alpha test as Material::alphaCutoff, a bound on the texture's alpha alone:
// glTF's alpha is baseColorFactor's alpha x the texture's, so a cutoff c on it is c / factor
// on the texture's (above 1: nothing passes). BLEND is tested as MASK at 0.5: ispm has no
// partly transparent surface, and a blended leaf or fence is mostly 0 or 1 (docs/scene-format.md).
float readAlphaCutoff(const GltfFile& file, const tinygltf::Material& in, double factorAlpha,
                      const std::string& at) {
    double cutoff = 0.0;
    if (in.alphaMode == "MASK") {
        cutoff = in.alphaCutoff;
        if (!(cutoff >= 0.0 && std::isfinite(cutoff))) {
            file.fail(at + "/alphaCutoff", strCat("a number >= 0, got ", cutoff));
        }
    } else if (in.alphaMode == "BLEND") {
        cutoff = kBlendAlphaCutoff;
    } else if (in.alphaMode != "OPAQUE") {
        file.fail(at + "/alphaMode", strCat("OPAQUE, MASK or BLEND, got '", in.alphaMode, "'"));
    }
    if (cutoff <= 0.0) return 0.0f;
    return factorAlpha > 0.0 ? float(std::min(cutoff / factorAlpha, kNothingPasses))
                             : float(kNothingPasses);
}

// A material's normalTexture (docs/design.md "Normal maps"): its image as a linear RGB texture,
// its scale, and TEXCOORD_0, the set ispm reads for it, which the base colour texture must share
// (one set per material).
void readNormalTexture(const GltfFile& file, const tinygltf::NormalTextureInfo& in,
                       const std::string& at, int& texcoordSet,
                       std::vector<uint32_t>& imageTextures, Scene& scene, Material& m) {
    if (in.texCoord != 0) {
        file.fail(at + "/texCoord",
                  strCat("0 (ispm reads normal maps at TEXCOORD_0), got ", in.texCoord));
    }
    if (texcoordSet > 0) {
        file.fail(at + "/texCoord",
                  strCat("the base colour texture's set ", texcoordSet,
                         " (ispm reads one set per material and normal maps at TEXCOORD_0)"));
    }
    if (!(std::isfinite(in.scale) && std::abs(in.scale) <= kMaxNormalScale)) {
        file.fail(at + "/scale", strCat("a number in [-", kMaxNormalScale, ", ", kMaxNormalScale,
                                        "], got ", in.scale));
    }
    m.normalTexture = importTexture(file, in.index, at + "/index", imageTextures, scene);
    // A grey image has no direction to give: the normal needs x, y and z.
    const int source = file.model.textures[static_cast<size_t>(in.index)].source;
    const int channels = file.model.images[static_cast<size_t>(source)].component;
    if (channels < 3) {
        file.fail(strCat("/images/", source),
                  strCat("an RGB or RGBA image (normalTexture ", in.index, " at ", at,
                         " uses it as a normal map), got ", channels, " channel(s)"));
    }
    m.normalScale = float(in.scale);
    texcoordSet = 0;
}

} // namespace

GltfMaterials importGltfMaterials(const GltfFile& file, const std::string& prefix, Scene& scene) {
    const tinygltf::Model& model = file.model;
    GltfMaterials out;
    std::vector<uint32_t> imageTextures(model.images.size(), kNoTexture);
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& in = model.materials[i];
        const std::string at = strCat("/materials/", i);
        const std::string pbrAt = at + "/pbrMetallicRoughness";
        const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
        const glm::vec3 base =
            readUnitColor(file, pbr.baseColorFactor, 4, pbrAt + "/baseColorFactor");
        const auto metallic = float(readUnit(file, pbr.metallicFactor, pbrAt + "/metallicFactor"));
        const auto roughness =
            float(readUnit(file, pbr.roughnessFactor, pbrAt + "/roughnessFactor"));
        int texcoordSet = -1;
        uint32_t texture = kNoTexture;
        glm::vec3 textureMean(1.0f);
        if (pbr.baseColorTexture.index >= 0) {
            texture = importTexture(file, pbr.baseColorTexture.index,
                                    pbrAt + "/baseColorTexture/index", imageTextures, scene);
            textureMean = computeLinearMean(scene.textures[texture]);
            texcoordSet = pbr.baseColorTexture.texCoord;
        }
        Material m = convertMetallicRoughness(base, metallic, roughness, textureMean);
        m.diffuseTexture = texture;
        if (in.normalTexture.index >= 0) {
            readNormalTexture(file, in.normalTexture, at + "/normalTexture", texcoordSet,
                              imageTextures, scene, m);
        }
        m.alphaCutoff = readAlphaCutoff(
            file, in, readUnit(file, pbr.baseColorFactor[3], pbrAt + "/baseColorFactor/3"), at);
        m.doubleSided = in.doubleSided;
        // Emission: radiance W/(m^2 sr) = factor x KHR_materials_emissive_strength (x the
        // emissive texture's mean: it cannot vary per point).
        glm::vec3 emission = readUnitColor(file, in.emissiveFactor, 3, at + "/emissiveFactor");
        emission *= readExtensionNumber(file, in.extensions, "KHR_materials_emissive_strength",
                                        "emissiveStrength", 1.0f, at);
        if (in.emissiveTexture.index >= 0 && emission != glm::vec3(0.0f)) {
            const uint32_t t = importTexture(file, in.emissiveTexture.index,
                                             at + "/emissiveTexture/index", imageTextures, scene);
            emission *= computeLinearMean(scene.textures[t]);
        }
        m.emission = emission;
        // A double-sided emissive surface emits from both sides (as Blender's emission does).
        m.emissionTwoSided = in.doubleSided;
        m.name = prefix + (in.name.empty() ? strCat("material_", i) : in.name);
        const std::string problem = checkMaterialEnergy(m);
        if (!problem.empty()) file.fail(at, problem);
        out.sceneIndex.push_back(static_cast<uint32_t>(scene.materials.size()));
        out.texcoordSet.push_back(texcoordSet);
        scene.materials.push_back(std::move(m));
    }
    return out;
}

uint32_t getGltfDefaultMaterial(GltfMaterials& materials, const std::string& prefix, Scene& scene) {
    if (materials.defaultMaterial == kNoTexture) {
        // glTF 2.0, 3.9.6: a primitive without a material is white, metallic 1, roughness 1.
        Material m = convertMetallicRoughness(glm::vec3(1.0f), 1.0f, 1.0f, glm::vec3(1.0f));
        m.name = prefix + "default";
        materials.defaultMaterial = static_cast<uint32_t>(scene.materials.size());
        scene.materials.push_back(std::move(m));
    }
    return materials.defaultMaterial;
}

Light convertGltfLight(const GltfFile& file, int index, const glm::mat4& worldFromNode,
                       const std::string& usePath) {
    const tinygltf::Model& model = file.model;
    if (index < 0 || static_cast<size_t>(index) >= model.lights.size()) {
        file.fail(usePath, strCat("a KHR_lights_punctual light index below ", model.lights.size(),
                                  ", got ", index));
    }
    const tinygltf::Light& in = model.lights[static_cast<size_t>(index)];
    const std::string at = strCat("/extensions/KHR_lights_punctual/lights/", index);
    // Colour is linear RGB in [0, 1] (default white); intensity is cd or lux.
    const glm::vec3 color =
        in.color.empty() ? glm::vec3(1.0f) : readUnitColor(file, in.color, 3, at + "/color");
    const double maxPhotometric = kMaxLightPower * double(kLumensPerWatt);
    if (!(in.intensity >= 0.0 && in.intensity <= maxPhotometric)) {
        file.fail(at + "/intensity",
                  strCat("a number in [0, ", maxPhotometric, "], got ", in.intensity));
    }
    const glm::vec3 photometric = color * float(in.intensity);
    Light light;
    light.position = glm::vec3(worldFromNode[3]);
    const glm::vec3 axis = glm::vec3(worldFromNode * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    light.direction = glm::normalize(axis);
    if (in.type == "point") {
        light.type = LightType::Point;
        light.intensity = convertCandelaToWattsPerSr(photometric);
    } else if (in.type == "spot") {
        light.type = LightType::Spot;
        light.intensity = convertCandelaToWattsPerSr(photometric);
        const double outer = in.spot.outerConeAngle;
        const double inner = in.spot.innerConeAngle;
        if (!(outer > 0.0 && outer <= std::numbers::pi / 2.0)) {
            file.fail(at + "/spot/outerConeAngle", "an angle in (0, pi/2] radians");
        }
        if (!(inner >= 0.0 && inner < outer)) {
            file.fail(at + "/spot/innerConeAngle", "an angle in [0, outerConeAngle) radians");
        }
        light.outerDeg = std::min(float(glm::degrees(outer)), kMaxSpotHalfAngleDeg);
        light.innerDeg = std::min(float(glm::degrees(inner)), light.outerDeg);
    } else if (in.type == "directional") {
        light.type = LightType::Sun;
        light.irradiance = convertLuxToWattsPerM2(photometric);
    } else {
        file.fail(at + "/type", strCat("point, spot or directional, got '", in.type, "'"));
    }
    if (!(glm::length(axis) > 0.0f) ||
        !std::isfinite(light.position.x + light.position.y + light.position.z)) {
        file.fail(usePath, "a node with an invertible, finite transform");
    }
    return light;
}

} // namespace ispm
