// The scene's texture array (GpuScene) and the texture coordinates of its vertices
// (vertex_attributes.glsl): the diffuse reflectance of a textured material at a
// point. Untextured materials never sample.
#ifndef ISPM_SCENE_TEXTURES_GLSL
#define ISPM_SCENE_TEXTURES_GLSL
// Include after lib/scene_buffers.glsl (its triangles and GpuMaterial).
#include "vertex_attributes.glsl"

layout(binding = kUnitSceneTextures) uniform sampler2DArray uSceneTextures;

bool hasDiffuseTexture(GpuMaterial m) {
    return m.diffuse.w > 0.0;
}

float getDiffuseTextureLayer(GpuMaterial m) {
    return m.diffuse.w - 1.0;
}

// Texture coordinates at barycentrics b of triangle `triangle` (b weights vertices y and z, as
// intersectTriangle reports them).
vec2 interpolateTexcoord(uint triangle, vec2 b) {
    uvec4 t = triangles[triangle];
    return (1.0 - b.x - b.y) * vertexAttributes[t.x].xy + b.x * vertexAttributes[t.y].xy +
           b.y * vertexAttributes[t.z].xy;
}

// The diffuse reflectance where a ray hit: a ray has no footprint, so the finest level.
vec3 getHitDiffuse(GpuMaterial m, uint triangle, vec2 barycentric) {
    if (!hasDiffuseTexture(m)) return m.diffuse.rgb;
    vec2 uv = interpolateTexcoord(triangle, barycentric);
    return m.diffuse.rgb *
           textureLod(uSceneTextures, vec3(uv, getDiffuseTextureLayer(m)), 0.0).rgb;
}

// Whether the material's alpha test cuts the point where a ray hit out (GpuMaterial::surface.x;
// the finest level, as getHitDiffuse). Only alpha-tested instances ask (bvh.glsl).
bool isHitCutOut(GpuMaterial m, uint triangle, vec2 barycentric) {
    float alpha = 1.0;
    if (hasDiffuseTexture(m)) {
        vec2 uv = interpolateTexcoord(triangle, barycentric);
        alpha = textureLod(uSceneTextures, vec3(uv, getDiffuseTextureLayer(m)), 0.0).a;
    }
    return alpha < m.surface.x;
}
#endif
