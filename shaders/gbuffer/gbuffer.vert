// G-buffer vertex stage: pulls the triangle's three vertices from the scene buffers, so the flat
// face normal needs no extra vertex data; the corners' shading normals and tangents, where the
// mesh has them, are interpolated beside it. One draw per instance.
#include "lib/scene_buffers.glsl"
#include "lib/vertex_attributes.glsl"
#if GBUFFER_TEXTURES
#include "lib/scene_textures.glsl"
#endif

layout(std140, binding = kBindingPassParams) uniform GBufferParamsBlock { GBufferParams params; };

layout(std430, binding = kBindingPreviousTransforms) readonly buffer PreviousTransforms {
    mat4 previousWorldFromObject[];
};

out vec3 vPositionW;
#if GBUFFER_TEXTURES
out vec2 vTexcoord;
// The corner's world-space tangent (not unit), the frame's handedness in world space (0: the
// triangle has no tangent frame), and the material's normal map (GpuMaterial::surface.zw).
out vec3 vTangentW;
flat out float vHandedness;
flat out vec2 vNormalMap;
#endif
#if !GBUFFER_LIGHT_VIEWS
// This frame's and the last frame's clip positions (velocity), divided per fragment.
out vec4 vClip;
out vec4 vPreviousClip;
#endif
flat out vec3 vNormalW;
// The corner's shading normal in world space (not unit: normalised per fragment), read where
// vSmooth is 1 (every corner has one; else the triangle is flat-shaded).
out vec3 vShadingNormalW;
flat out uint vSmooth;
// The triangle's material, read here (three times a triangle) rather than per fragment: there
// the flat index makes its storage-buffer load a gather per pixel on llvmpipe (a fifth of the
// light views' time on the thesis preset).
flat out vec4 vDiffuse;
flat out vec4 vSpecular;
flat out vec4 vTransmissive;
#if !GBUFFER_LIGHT_VIEWS
flat out vec4 vEmission; // w = 1: both sides emit
#endif
#if GBUFFER_ALPHA_TEST
flat out float vAlphaCutoff;
#endif
flat out uint vInstance;

void main() {
    uint instance = params.instance;
    GpuInstance inst = instances[instance];
    uvec4 tri = triangles[inst.range.x + uint(gl_VertexID) / 3u];
    vec3 p0 = positions[tri.x].xyz;
    vec3 p1 = positions[tri.y].xyz;
    vec3 p2 = positions[tri.z].xyz;
    uint corner = uint(gl_VertexID) % 3u;
    uint vertex = corner == 0u ? tri.x : (corner == 1u ? tri.y : tri.z);
    vec3 p = corner == 0u ? p0 : (corner == 1u ? p1 : p2);
#if GBUFFER_TEXTURES
    vTexcoord = vertexAttributes[vertex].texcoord;
    vec4 tangent = vertexAttributes[vertex].tangent;
    bool framed = vertexAttributes[tri.x].tangent.w != 0.0 &&
                  vertexAttributes[tri.y].tangent.w != 0.0 &&
                  vertexAttributes[tri.z].tangent.w != 0.0;
    // A mirroring transform turns cross(n, t) around: the handedness follows it.
    float mirror = determinant(mat3(inst.worldFromObject)) < 0.0 ? -1.0 : 1.0;
    vHandedness = framed ? mirror * vertexAttributes[tri.x].tangent.w : 0.0;
    vTangentW = mat3(inst.worldFromObject) * tangent.xyz;
#endif
    vec4 positionW = inst.worldFromObject * vec4(p, 1.0);
    vPositionW = positionW.xyz;
    mat3 normalFromObject = transpose(mat3(inst.objectFromWorld));
    vNormalW = normalize(normalFromObject * cross(p1 - p0, p2 - p0));
    vSmooth = hasShadingNormals(tri) ? 1u : 0u;
    vShadingNormalW = vSmooth != 0u ? normalFromObject * getShadingNormal(vertex) : vNormalW;
    GpuMaterial m = materials[tri.w];
    vDiffuse = m.diffuse;
    vSpecular = m.specular;
    vTransmissive = m.transmissive;
#if !GBUFFER_LIGHT_VIEWS
    vEmission = m.emission;
#endif
#if GBUFFER_ALPHA_TEST
    vAlphaCutoff = m.surface.x;
#endif
#if GBUFFER_TEXTURES
    vNormalMap = m.surface.zw;
#endif
    vInstance = instance;
    gl_Position = params.clipFromWorld * positionW;
#if !GBUFFER_LIGHT_VIEWS
    vClip = gl_Position;
    vPreviousClip =
        params.previousClipFromWorld * (previousWorldFromObject[instance] * vec4(p, 1.0));
#endif
}
