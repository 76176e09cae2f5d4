// Texture coordinates per vertex and the scene's texture array (GpuScene): the diffuse
// reflectance of a textured material at a point. Untextured materials never sample.
#ifndef ISPM_SCENE_TEXTURES_GLSL
#define ISPM_SCENE_TEXTURES_GLSL
// Include after lib/scene_buffers.glsl (its triangles and GpuMaterial).

layout(std430, binding = kBindingTexcoords) readonly buffer SceneTexcoords { vec2 texcoords[]; };
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
    return (1.0 - b.x - b.y) * texcoords[t.x] + b.x * texcoords[t.y] + b.y * texcoords[t.z];
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
