// Splat fragment stage: the viewer G-buffer point under the pixel receives the photon when it lies
// inside the photon's ellipsoid and faces the same way; it gets BRDF x power x kernel, the kernel
// 2 / (pi r^2) (1 - s^2 / r^2) over the in-plane distance s, which integrates to 1 over the disc
// of radius r: one photon's power is conserved on a flat surface.
#include "lib/frame_constants.glsl"
#include "lib/brdf.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"

layout(std430, binding = kBindingResultPhotons) readonly buffer ResultBuffer { ResultPhoton photons[]; };
layout(std140, binding = kBindingPassParams) uniform SplatParamsBlock { SplatParams params; };

layout(binding = kUnitGBufferFirst + GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = kUnitGBufferFirst + GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = kUnitGBufferFirst + GBUFFER_DIFFUSE) uniform sampler2D uDiffuse;
layout(binding = kUnitGBufferFirst + GBUFFER_SPECULAR) uniform sampler2D uSpecular;

flat in uint vPhoton;
flat in float vRadius;
flat in uint vClipped;

// Per photon: kClipRays / 2 vec4s of two poles each, then the box extents (shared/splat_clip.h).
layout(std430, binding = kBindingSplatClip) readonly buffer SplatClip { vec4 splatClip[]; };

layout(location = 0) out vec4 outRadiance;

void main() {
    if (params.control.y == 1u && gl_FrontFacing) discard; // splat_faces = all
    // A buffer smaller than the image shades the G-buffer pixel at the middle of its block.
    ivec2 pixel = getBlockGBufferPixel(ivec2(gl_FragCoord.xy), int(params.shape.y));
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) discard;
    ResultPhoton photon = photons[vPhoton];
    vec3 pn = photon.normalDensity.xyz;
    vec3 n = texelFetch(uNormal, pixel, 0).xyz;
    if (dot(n, pn) <= 0.0) discard; // the surface faces away from where the photon arrived
    vec3 d = position.xyz - photon.positionDistance.xyz;
    float along = dot(d, pn);
    vec3 inPlane = d - along * pn;
    float s2 = dot(inPlane, inPlane) / (vRadius * vRadius);
    float z = along / (vRadius * params.shape.x);
    if (s2 + z * z > 1.0) discard;
    // Beyond a clip line lies another surface (a wall the disc would climb or pass through).
    vec3 t;
    vec3 b;
    buildSplatBasis(pn, t, b);
    vec2 x = vec2(dot(inPlane, t), dot(inPlane, b));
    vec2 poles[kClipRays];
    for (uint i = 0u; i < kClipRays / 2u; ++i) {
        vec4 two = vClipped == 1u ? splatClip[vPhoton * kClipVec4s + i] : vec4(0.0);
        poles[2u * i] = two.xy;
        poles[2u * i + 1u] = two.zw;
    }
    for (uint i = 0u; i < kClipRays; ++i) {
        if (isBeyondLine(x, poles[i])) discard;
    }
    // Gather-style renormalisation: the pixel's own disc (radius r, centred on it) is cut by the
    // same lines; dividing by the part of it that lies on the surface keeps a uniform irradiance
    // uniform up to the wall, and the photon's power on the surfaces it reached.
    float keptMass = computeKeptMass(x, poles, vRadius);
    float kernel = 2.0 * kInvPi / (vRadius * vRadius) * (1.0 - s2);
    vec3 wi = -photon.incoming.xyz;
    vec3 wo = normalize(frame.cameraPosition.xyz - position.xyz);
    vec3 f = evaluateBrdf(texelFetch(uDiffuse, pixel, 0).rgb, texelFetch(uSpecular, pixel, 0), n, wi, wo);
    outRadiance = vec4(f * photon.power.rgb * (kernel / keptMass), 1.0);
}
