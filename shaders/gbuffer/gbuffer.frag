// G-buffer fragment stage: writes the channels of the table in app/render/gbuffer.cpp.
#include "lib/scene_buffers.glsl"

layout(std140, binding = kBindingPassParams) uniform GBufferParamsBlock { GBufferParams params; };

in vec3 vPositionW;
in vec4 vClip;
in vec4 vPreviousClip;
flat in vec3 vNormalW;
flat in uint vMaterial;
flat in uint vInstance;

layout(location = GBUFFER_POSITION) out vec4 outPosition;
layout(location = GBUFFER_NORMAL) out vec4 outNormal;
layout(location = GBUFFER_DIFFUSE) out vec4 outDiffuse;
layout(location = GBUFFER_SPECULAR) out vec4 outSpecular;
layout(location = GBUFFER_TRANSMISSIVE) out vec4 outTransmissive;
layout(location = GBUFFER_EMISSION) out vec4 outEmission;
layout(location = GBUFFER_VELOCITY) out vec2 outVelocity; // viewer only (dropped for lights)

void main() {
    vec4 eye = params.eye;
    vec3 toEye = eye.w > 0.5 ? eye.xyz - vPositionW : eye.xyz;
    // Surfaces are two-sided: the normal faces whoever looks at it.
    bool frontFace = dot(vNormalW, toEye) >= 0.0;
    vec3 n = frontFace ? vNormalW : -vNormalW;
    GpuMaterial m = materials[vMaterial];
    // Instance + 1: >= 1 on a surface (exact in float up to 2^24 instances).
    outPosition = vec4(vPositionW, float(vInstance + 1u));
    outNormal = vec4(n, frontFace ? 1.0 : -1.0);
    outDiffuse = vec4(m.diffuse.rgb, 0.0);
    outSpecular = m.specular;
    outTransmissive = m.transmissive;
    outEmission = vec4(m.emission.rgb, 0.0);
    // A point behind the last frame's eye has no place in its image: no motion.
    vec2 motionNdc = vPreviousClip.w > 0.0
                         ? vClip.xy / vClip.w - vPreviousClip.xy / vPreviousClip.w
                         : vec2(0.0);
    outVelocity = motionNdc * params.pixelScale.xy - params.pixelScale.zw;
}
