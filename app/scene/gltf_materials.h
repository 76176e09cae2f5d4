// glTF materials and lights to the scene model (the mappings are in gltf_units.h and
// docs/scene-format.md). Internal to the glTF importer.
#pragma once

#include "scene/gltf_accessors.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace ispm {

struct GltfMaterials {
    std::vector<uint32_t> sceneIndex;      // per glTF material: its index in Scene::materials
    std::vector<int> texcoordSet;          // per glTF material: TEXCOORD_n of its texture, or -1
    uint32_t defaultMaterial = kNoTexture; // glTF's default material, added when first used
};

// Adds every material of the file (and the images their base colour textures use) to `scene`;
// `prefix` names them ("file.gltf:" + the material's name).
GltfMaterials importGltfMaterials(const GltfFile& file, const std::string& prefix, Scene& scene);

// The scene index of glTF's default material (white, metallic 1, roughness 1), added once.
uint32_t getGltfDefaultMaterial(GltfMaterials& materials, const std::string& prefix, Scene& scene);

// KHR_lights_punctual light `index` placed by a node's world transform (the light shines along
// its -z axis), in ispm's units.
Light convertGltfLight(const GltfFile& file, int index, const glm::mat4& worldFromNode,
                       const std::string& usePath);

} // namespace ispm
