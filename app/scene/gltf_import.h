// glTF 2.0 (.gltf with its buffers and images, or .glb) to the scene model, through tinygltf:
// meshes placed by their nodes, metallic-roughness materials with base colour textures,
// KHR_lights_punctual lights and perspective cameras. The mapping is documented in
// docs/scene-format.md ("glTF"); a malformed file is an InputError naming the file and JSON path.
#pragma once

#include "scene/scene.h"

#include <string>
#include <utility>
#include <vector>

namespace ispm {

// Adds the file's default scene (else its first, else every root node) to `scene`: a mesh per
// glTF mesh, an instance per node holding one (worldFromFile x the node's world transform),
// materials, textures and lights. Returns the perspective cameras of its nodes, in node order,
// named after the camera (else the node). Throws InputError when it adds no triangle.
std::vector<std::pair<std::string, Camera>>
importGltf(const std::string& path, const glm::mat4& worldFromFile, Scene& scene);

// A scene of one glTF file: its first camera (else one on +z looking at the middle of its
// bounds), every camera as a named camera, black background, default settings.
Scene loadGltfScene(const std::string& path);

// Whether the path names a glTF file (.gltf or .glb, any case).
bool isGltfPath(const std::string& path);

} // namespace ispm
