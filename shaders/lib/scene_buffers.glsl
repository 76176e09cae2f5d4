// Read-only views of the scene's storage buffers (layouts in shared/scene_data.h).
#include "../shared/scene_data.h"

layout(std430, binding = kBindingPositions) readonly buffer ScenePositions { vec4 positions[]; };
layout(std430, binding = kBindingTriangles) readonly buffer SceneTriangles { uvec4 triangles[]; };
layout(std430, binding = kBindingInstances) readonly buffer SceneInstances { GpuInstance instances[]; };
layout(std430, binding = kBindingMaterials) readonly buffer SceneMaterials { GpuMaterial materials[]; };
layout(std430, binding = kBindingLights) readonly buffer SceneLights { GpuLight lights[]; };
layout(std430, binding = kBindingLightViews) readonly buffer SceneLightViews { GpuLightView lightViews[]; };
