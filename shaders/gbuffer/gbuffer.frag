// G-buffer fragment stage: writes the channels of the table in app/render/gbuffer.cpp.
#include "lib/scene_buffers.glsl"
#include "lib/vertex_attributes.glsl"
#if GBUFFER_TEXTURES // the textured variant (GBufferPrograms)
#include "lib/scene_textures.glsl"
#endif

layout(std140, binding = kBindingPassParams) uniform GBufferParamsBlock { GBufferParams params; };

in vec3 vPositionW;
#if GBUFFER_TEXTURES
in vec2 vTexcoord;
in vec3 vTangentW;
flat in float vHandedness;
flat in vec2 vNormalMap;
#endif
#if !GBUFFER_LIGHT_VIEWS
in vec4 vClip;
in vec4 vPreviousClip;
#endif
flat in vec3 vNormalW;
in vec3 vShadingNormalW;
flat in uint vSmooth;
flat in vec4 vDiffuse;
flat in vec4 vSpecular;
flat in vec4 vTransmissive;
#if !GBUFFER_LIGHT_VIEWS
flat in vec4 vEmission; // w = 1: both sides emit
#endif
#if GBUFFER_ALPHA_TEST
flat in float vAlphaCutoff;
#endif
flat in uint vInstance;

layout(location = GBUFFER_POSITION) out vec4 outPosition;
layout(location = GBUFFER_NORMAL) out vec4 outNormal;
layout(location = GBUFFER_DIFFUSE) out vec4 outDiffuse;
layout(location = GBUFFER_SPECULAR) out vec4 outSpecular;
layout(location = GBUFFER_TRANSMISSIVE) out vec4 outTransmissive;
#if !GBUFFER_LIGHT_VIEWS // the viewer-only channels
layout(location = GBUFFER_EMISSION) out vec4 outEmission;
layout(location = GBUFFER_VELOCITY) out vec2 outVelocity;
#endif

void main() {
    vec4 eye = params.eye;
    vec3 toEye = eye.w > 0.5 ? eye.xyz - vPositionW : eye.xyz;
    // Surfaces are two-sided: the normal faces whoever looks at it.
    bool frontFace = dot(vNormalW, toEye) >= 0.0;
    vec3 geometric = frontFace ? vNormalW : -vNormalW;
    vec3 n = geometric;
    // The channel holds the shading normal, on the geometric normal's side (the side the eye
    // sees); w keeps which face that is. Readers use it for the BRDF's cosines and for their
    // hemisphere tests and ray offsets alike: a second normal would cost a channel on every
    // scene, and the shading normal on the seen side still offsets rays to that side.
    if (vSmooth != 0u) n = orientShadingNormal(vShadingNormalW, geometric);
#if GBUFFER_TEXTURES
    // A normal map turns the front's normal in its tangent frame, then the result is turned to
    // the seen side as any shading normal (the back of a two-sided surface: reversed). The
    // branch is uniform over each triangle, as the colour texture's below.
    if (vNormalMap.x > 0.0 && vHandedness != 0.0) {
        vec3 front = vSmooth != 0u ? vShadingNormalW : vNormalW;
        vec3 mapped = decodeNormalTexel(
            texture(uSceneNormalMaps, vec3(vTexcoord, vNormalMap.x - 1.0)).rgb, vNormalMap.y);
        n = orientShadingNormal(perturbNormal(front, vec4(vTangentW, vHandedness), mapped),
                                geometric);
    }
#endif
#if GBUFFER_LIGHT_VIEWS
    const vec3 emission = vec3(0.0); // light views keep no emission
#else
    // One-sided emitters emit from the side their winding faces (lib/emitters.glsl).
    vec3 emission = frontFace || vEmission.w > 0.5 ? vEmission.rgb : vec3(0.0);
#endif
    GpuMaterial m = GpuMaterial(vDiffuse, vSpecular, vTransmissive, vec4(emission, 0.0),
#if GBUFFER_ALPHA_TEST
                                vec4(vAlphaCutoff, 0.0, 0.0, 0.0)
#else
                                vec4(0.0)
#endif
    );
    // Instance + 1: >= 1 on a surface (exact in float up to 2^24 instances).
    outPosition = vec4(vPositionW, float(vInstance + 1u));
    outNormal = vec4(n, frontFace ? 1.0 : -1.0);
    // Textured: the base colour texture, mipmapped by the pixel's footprint (light views too:
    // a photon's first bounce takes the colour its texel of the light's image averages). The
    // branch is uniform over each 2x2 quad (a quad is one triangle's, the material is flat), so
    // the implicit derivatives are defined, and untextured surfaces pay for no lookup.
    vec3 diffuse = m.diffuse.rgb;
    float alpha = 1.0;
#if GBUFFER_TEXTURES
    if (hasDiffuseTexture(m)) {
        vec4 texel = texture(uSceneTextures, vec3(vTexcoord, getDiffuseTextureLayer(m)));
        diffuse *= texel.rgb;
        alpha = texel.a;
    }
#endif
#if GBUFFER_ALPHA_TEST
    // Cut out as the rays' test cuts it (isHitCutOut), but at the pixel's mip level: a leaf
    // seen from afar keeps the shape its filtered texels give it.
    if (alpha < vAlphaCutoff) discard;
#endif
    outDiffuse = vec4(diffuse, 0.0);
    outSpecular = m.specular;
    outTransmissive = m.transmissive;
#if !GBUFFER_LIGHT_VIEWS
    outEmission = vec4(m.emission.rgb, 0.0);
    // A point behind the last frame's eye has no place in its image: no motion.
    vec2 motionNdc = vPreviousClip.w > 0.0
                         ? vClip.xy / vClip.w - vPreviousClip.xy / vPreviousClip.w
                         : vec2(0.0);
    outVelocity = motionNdc * params.halfTargetSizePx - params.jitterMotionPx;
#endif
}
