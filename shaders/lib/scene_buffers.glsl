// Read-only views of the scene's storage buffers (layouts in shared/scene_data.h).
#include "../shared/scene_data.h"

layout(std430, binding = kBindingPositions) readonly buffer ScenePositions { vec4 positions[]; };
layout(std430, binding = kBindingTriangles) readonly buffer SceneTriangles { uvec4 triangles[]; };
layout(std430, binding = kBindingInstances) readonly buffer SceneInstances { GpuInstance instances[]; };
layout(std430, binding = kBindingMaterials) readonly buffer SceneMaterials { GpuMaterial materials[]; };
layout(std430, binding = kBindingLights) readonly buffer SceneLights { GpuLight lights[]; };
layout(std430, binding = kBindingLightViews) readonly buffer SceneLightViews { GpuLightView lightViews[]; };

#ifndef ISPM_RAY_OFFSET_GLSL
#define ISPM_RAY_OFFSET_GLSL
// How far a ray's origin leaves the surface at p: 1e-5 of p's largest coordinate magnitude
// (about 100x float's precision there), and at least `floorM` (GpuScene::getRayEpsilon, from
// the scene's smallest part). One offset for the whole scene, from its extent, is wider than a
// small room beside a huge distant object, and lets every ray leave the room.
float computeRayOffset(vec3 p, float floorM) {
    vec3 a = abs(p);
    return max(floorM, 1e-5 * max(a.x, max(a.y, a.z)));
}
#endif
