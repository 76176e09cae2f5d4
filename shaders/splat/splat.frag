// Splat fragment stage: the viewer G-buffer point under the pixel receives the photon when it lies
// inside the photon's ellipsoid and faces the same way; it gets BRDF x power x kernel, the kernel
// 2 / (pi r^2) (1 - s^2 / r^2) over the in-plane distance s, which integrates to 1 over the disc
// of radius r: one photon's power is conserved on a flat surface.
#include "lib/frame_constants.glsl"
#include "lib/brdf.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"
#include "shared/splat_clip.h"

layout(std140, binding = kBindingPassParams) uniform SplatParamsBlock { SplatParams params; };

#include "lib/viewer_gbuffer.glsl"

flat in vec4 vCentre;
flat in vec3 vNormal;
flat in vec3 vTangent;
flat in vec3 vBitangent;
flat in vec3 vPower;
flat in vec3 vIncoming;
flat in uint vLines;
flat in vec2 vPoles[kClipRays];

layout(location = 0) out vec4 outRadiance;

void main() {
    // A buffer smaller than the image shades the G-buffer pixel at the middle of its block.
    ivec2 pixel = getBlockGBufferPixel(ivec2(gl_FragCoord.xy), int(params.shape.y));
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) discard;
    vec3 pn = vNormal;
    vec3 n = texelFetch(uNormal, pixel, 0).xyz;
    if (dot(n, pn) <= 0.0) discard; // the surface faces away from where the photon arrived
    float radius = vCentre.w;
    vec3 d = position.xyz - vCentre.xyz;
    float along = dot(d, pn);
    vec3 inPlane = d - along * pn;
    float s2 = dot(inPlane, inPlane) / (radius * radius);
    float z = along / (radius * params.shape.x);
    if (s2 + z * z > 1.0) discard;
    // Beyond a clip line lies another surface (a wall the disc would climb or pass through).
    vec2 x = vec2(dot(inPlane, vTangent), dot(inPlane, vBitangent));
    // Gather-style renormalisation: the pixel's own disc (radius r, centred on it) is cut by the
    // same lines; dividing by the part of it that lies on the surface keeps a uniform irradiance
    // uniform up to the wall, and the photon's power on the surfaces it reached.
    for (uint i = 0u; i < vLines; ++i) {
        if (isBeyondLine(x, vPoles[i])) discard;
    }
    float keptMass = computeKeptMass(x, vPoles, radius);
    float kernel = 2.0 * kInvPi / (radius * radius) * (1.0 - s2);
    vec3 wi = -vIncoming;
    vec3 wo = normalize(frame.cameraPosition.xyz - position.xyz);
    vec3 f = evaluateBrdf(texelFetch(uDiffuse, pixel, 0).rgb, texelFetch(uSpecular, pixel, 0), n, wi, wo);
    outRadiance = vec4(f * vPower * (kernel / keptMass), 1.0);
}
