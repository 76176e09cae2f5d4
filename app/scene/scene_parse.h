// The scene loader's internal pieces, shared by its source files: the parse context, materials
// and objects. Not part of ispm_scene's public interface.
#pragma once

#include "scene/json_reader.h"
#include "scene/scene.h"

#include <map>
#include <string>

namespace ispm {

struct ParseContext {
    Scene& scene;
    std::string baseDir;
    std::map<std::string, uint32_t, std::less<>> materialsByName; // from the `materials` block
};

// Reflectances must lie in [0,1] and sum to at most 1 per channel (within this slack, so that
// 0.5 + 0.3 + 0.2 written in decimal passes); ior >= 1; phong exponent and emission >= 0.
inline constexpr float kEnergySlack = 1e-5f;
inline constexpr float kMinIor = 1.0f;

// Empty when the material is acceptable, else the "expected ..." text for the message.
std::string checkMaterialEnergy(const Material& material);

void parseMaterials(const JsonNode& materials, ParseContext& context);
// A material name from the `materials` block or an inline material object.
uint32_t resolveMaterial(const JsonNode& node, ParseContext& context);

void parseObject(const JsonNode& object, size_t index, ParseContext& context);

// An `area` light (element `index` of `lights`): an emitting rectangle or disc, added to the
// scene as a mesh with its own material (scene/area_lights.cpp).
void parseAreaLight(const JsonNode& node, size_t index, ParseContext& context);

// What an `animation` moves decides which motions it may use (docs/scene-format.md).
enum class AnimationTarget { Object, PointLight, SpotLight, SunLight };

// An `animation` object. rotate_deg_per_s turns about `defaultPivotW` unless a pivot is given.
Animation parseAnimation(const JsonNode& node, AnimationTarget target,
                         const glm::vec3& defaultPivotW);

} // namespace ispm
