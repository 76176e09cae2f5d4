// The scene's texture array (GpuScene) and the texture coordinates of its vertices
// (vertex_attributes.glsl): the diffuse reflectance of a textured material at a point, and
// the shading normal of a normal-mapped one. Untextured materials never sample.
#ifndef ISPM_SCENE_TEXTURES_GLSL
#define ISPM_SCENE_TEXTURES_GLSL
// Include after lib/scene_buffers.glsl (its triangles and GpuMaterial).
#include "vertex_attributes.glsl"

layout(binding = kUnitSceneTextures) uniform sampler2DArray uSceneTextures;
// Linear RGBA8, not sRGB: a normal map's bytes are a direction (GpuMaterial::surface.z).
layout(binding = kUnitSceneNormalMaps) uniform sampler2DArray uSceneNormalMaps;

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
    return (1.0 - b.x - b.y) * vertexAttributes[t.x].texcoord +
           b.x * vertexAttributes[t.y].texcoord + b.y * vertexAttributes[t.z].texcoord;
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

bool hasNormalMap(GpuMaterial m) {
    return m.surface.z > 0.0;
}

float getNormalMapLayer(GpuMaterial m) {
    return m.surface.z - 1.0;
}

// The tangent-space normal a normal map's texel gives (glTF normalTexture: 2 rgb - 1, x and y
// times the scale; not unit).
vec3 decodeNormalTexel(vec3 rgb, float scale) {
    return (2.0 * rgb - 1.0) * vec3(scale, scale, 1.0);
}

// The front's normal turned by a normal map (docs/design.md "Normal maps"): `front` the
// world-space normal of the side the winding faces (not unit), `tangent` xyz the world-space
// tangent along +u and w the handedness in world space, `mapped` decodeNormalTexel's. The tangent
// is made perpendicular to the normal first (interpolated frames drift apart). Not unit and not
// yet turned to any side: orientShadingNormal does both.
vec3 perturbNormal(vec3 front, vec4 tangent, vec3 mapped) {
    vec3 n = normalize(front);
    vec3 t = tangent.xyz - dot(tangent.xyz, n) * n;
    float length_ = length(t);
    if (!(length_ > 0.0)) return n;
    t /= length_;
    vec3 bitangent = tangent.w * cross(n, t); // up the image
    return mapped.x * t + mapped.y * bitangent + mapped.z * n;
}

// The world-space unit shading normal where a ray hit a normal-mapped material `m`, on the side
// of `geometric` (as computeShadingNormal): the finest level, as getHitDiffuse reads colour.
vec3 computeMappedShadingNormal(GpuMaterial m, uint triangle, uint instance, vec2 b,
                                vec3 geometric) {
    vec4 tangent = interpolateTangent(triangle, b);
    if (tangent.w == 0.0) return computeShadingNormal(triangle, instance, b, geometric);
    GpuInstance inst = instances[instance];
    mat3 worldFromObject = mat3(inst.worldFromObject);
    // A mirroring transform turns cross(n, t) around: the handedness follows it.
    float handedness = determinant(worldFromObject) < 0.0 ? -tangent.w : tangent.w;
    vec3 front = transpose(mat3(inst.objectFromWorld)) * interpolateFrontNormal(triangle, b);
    vec2 uv = interpolateTexcoord(triangle, b);
    vec3 mapped = decodeNormalTexel(
        textureLod(uSceneNormalMaps, vec3(uv, getNormalMapLayer(m)), 0.0).rgb, m.surface.w);
    return orientShadingNormal(
        perturbNormal(front, vec4(worldFromObject * tangent.xyz, handedness), mapped), geometric);
}
#endif
