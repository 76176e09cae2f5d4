// Materials of a scene file: the named `materials` block, inline material objects, and the
// energy-conservation check they share with materials imported from MTL files.
#include "core/strings.h"
#include "scene/scene_parse.h"

#include <cmath>

namespace ispm {

namespace {

constexpr const char* kChannelNames[] = {"red", "green", "blue"};

Material parseMaterial(const JsonNode& node, std::string name) {
    node.checkKeys({"diffuse", "specular", "phong_exponent", "transmissive", "ior", "emission",
                    "emission_two_sided", "photon_share"},
                   "a material");
    const NumberRange reflectance = NumberRange::getClosed(0.0, 1.0);
    Material material;
    material.name = std::move(name);
    if (auto v = node.find("diffuse")) material.diffuse = v->readVec3(reflectance);
    if (auto v = node.find("specular")) material.specular = v->readVec3(reflectance);
    if (auto v = node.find("transmissive")) material.transmissive = v->readVec3(reflectance);
    if (auto v = node.find("phong_exponent")) {
        material.phongExponent = v->readFloat(NumberRange::getAtLeast(0.0));
    }
    if (auto v = node.find("ior")) {
        material.ior = v->readFloat(NumberRange::getAtLeast(static_cast<double>(kMinIor)));
    }
    if (auto v = node.find("emission")) {
        // Bounded like light intensities (inf made NaN pixels).
        material.emission = v->readVec3(NumberRange::getClosed(0.0, 1e12));
    }
    if (auto v = node.find("emission_two_sided")) material.emissionTwoSided = v->readBool();
    if (auto v = node.find("photon_share")) {
        material.photonShare = v->readFloat(NumberRange::getClosed(0.0, 1.0));
    }
    const std::string problem = checkMaterialEnergy(material);
    if (!problem.empty()) node.fail(problem);
    return material;
}

} // namespace

std::string checkMaterialEnergy(const Material& m) {
    const auto isFinite = [](const glm::vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    const auto isUnit = [](const glm::vec3& v) {
        return glm::all(glm::greaterThanEqual(v, glm::vec3(0.0f))) &&
               glm::all(glm::lessThanEqual(v, glm::vec3(1.0f)));
    };
    if (!isUnit(m.diffuse) || !isUnit(m.specular) || !isUnit(m.transmissive)) {
        return "reflectances (diffuse, specular, transmissive) in [0, 1]";
    }
    if (!isFinite(m.emission) || glm::any(glm::lessThan(m.emission, glm::vec3(0.0f)))) {
        return "an emission of finite numbers >= 0";
    }
    if (!std::isfinite(m.phongExponent) || m.phongExponent < 0.0f) return "a phong_exponent >= 0";
    if (!std::isfinite(m.ior) || m.ior < kMinIor) return strCat("an ior >= ", kMinIor);
    for (int c = 0; c < 3; ++c) {
        const float sum = m.diffuse[c] + m.specular[c] + m.transmissive[c];
        if (sum > 1.0f + kEnergySlack) {
            return strCat("diffuse + specular + transmissive <= 1 in every channel (energy "
                          "conservation), got ",
                          formatFloat(m.diffuse[c]), " + ", formatFloat(m.specular[c]), " + ",
                          formatFloat(m.transmissive[c]), " = ", formatFloat(sum), " in ",
                          kChannelNames[c]);
        }
    }
    return "";
}

void parseMaterials(const JsonNode& materials, ParseContext& context) {
    materials.requireObject("materials by name");
    for (const auto& [name, node] : materials.getMembers()) {
        if (name.empty()) node.fail("a non-empty material name");
        node.requireObject("a material");
        context.materialsByName[name] = static_cast<uint32_t>(context.scene.materials.size());
        context.scene.materials.push_back(parseMaterial(node, name));
    }
}

uint32_t resolveMaterial(const JsonNode& node, ParseContext& context) {
    const nlohmann::json& value = node.getJson();
    if (value.is_string()) {
        const std::string name = value.get<std::string>();
        const auto it = context.materialsByName.find(name);
        if (it == context.materialsByName.end()) {
            std::string known;
            for (const auto& entry : context.materialsByName) {
                known += (known.empty() ? "" : ", ") + entry.first;
            }
            node.fail(strCat("a material defined in /materials (",
                             known.empty() ? "none are" : known, "), got unknown material '", name,
                             "'"));
        }
        return it->second;
    }
    if (value.is_object()) {
        // Inline materials are named by their JSON path: unique, and it says where they came from.
        context.scene.materials.push_back(parseMaterial(node, node.getPath()));
        return static_cast<uint32_t>(context.scene.materials.size() - 1);
    }
    node.failGot("a material name or a material object");
}

} // namespace ispm
