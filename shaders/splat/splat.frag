// Splat fragment stage: the viewer G-buffer point under the pixel receives the photon when it lies
// inside the photon's ellipsoid, on its side of every clip line, and faces the same way; it gets
// BRDF x power x the splat's weight (lib/splat_kernel.glsl).
#include "lib/frame_constants.glsl"
#include "lib/brdf.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"
#ifndef SCENE_NORMAL_MAPS
#define SCENE_NORMAL_MAPS 1
#endif

layout(std140, binding = kBindingPassParams) uniform SplatParamsBlock { SplatParams params; };

#include "lib/viewer_gbuffer.glsl"

// The kernel alone: splat.frag reads no photon buffer.
#define ISPM_SPLAT_WEIGHT_ONLY
#include "lib/splat_kernel.glsl"

flat in vec4 vCentre;
flat in vec3 vNormal;
flat in vec3 vTangent;
flat in vec3 vBitangent;
flat in vec3 vPower;
flat in vec3 vIncoming;
#if SPLAT_CLIP_LINES // splat_clip (SplatPass)
flat in uint vLines;
flat in vec2 vPoles[kClipRays];
flat in uint vWedges[kClipRays];
#endif

layout(location = 0) out vec4 outRadiance;

void main() {
    // A buffer smaller than the image shades the G-buffer pixel at the middle of its block; the
    // target drawn may hold the buffer at an offset (SplatPass::computeTargetOffset).
    ivec2 at = ivec2(gl_FragCoord.xy) - params.targetOffsetPx;
    ivec2 pixel = getBlockGBufferPixel(at, params.pixelsPerBufferPx);
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) discard;
    vec3 n = texelFetch(uNormal, pixel, 0).xyz;
#if SPLAT_CLIP_LINES
    float weight = computeSplatWeight(vCentre, vNormal, vTangent, vBitangent, vLines, vPoles,
                                      vWedges, params.squash, position.xyz, n);
#else
    vec2 x;
    float weight =
        computeSplatKernel(vCentre, vNormal, vTangent, vBitangent, params.squash, position.xyz, n, x);
#endif
    if (weight < 0.0) discard;
    vec3 wi = -vIncoming;
    vec3 wo = normalize(frame.cameraPosW - position.xyz);
    vec3 f = evaluateSplatBrdf(texelFetch(uDiffuse, pixel, 0).rgb, texelFetch(uSpecular, pixel, 0), n,
                               wi, wo, frame.specularTraceMinExponent);
#if SCENE_NORMAL_MAPS
    // A normal map turns the pixel's normal n from the surface's (the photon's disc normal): the
    // flux that crossed the surface lights the turned normal by |wi.n| / |wi.surface|, Veach's
    // adjoint factor at the receiving end (docs/design.md "Normal maps"); light from below the
    // turned normal's horizon lights nothing, as in the path tracer. Without maps the factor is
    // 1 but for the G-buffer's rounding, and is left out.
    const float kMinSurfaceCos = 0.01; // a photon this grazing would weigh a hundredfold
    f *= max(dot(wi, n), 0.0) / max(abs(dot(wi, vNormal)), kMinSurfaceCos);
#endif
    outRadiance = vec4(f * vPower * weight, 1.0);
}
