// Total radiance = direct + indirect + emission, and the background where no surface is. The
// direct light's alpha is the share of the pixel a surface covers (in one frame 1 or 0, or with
// edge_samples the share of the pixel's rays that hit one; averaged over accumulated frames,
// whose sub-pixel offsets move silhouettes), so silhouettes against the background come out
// anti-aliased too. The direct light is the mean over the pixel already (0 where a ray saw the
// background); the indirect light is the surface's (at the pixel's centre, or averaged over the
// frames whose centre hit it: accumulate.frag) and covers that share of the pixel.
#include "lib/frame_constants.glsl"

#include "lib/viewer_gbuffer.glsl"
layout(binding = kUnitDirect) uniform sampler2D uDirect;
layout(binding = kUnitIndirect) uniform sampler2D uIndirect;
#if COMPOSE_ENVIRONMENT // a scene with an environment (ComposePass): seen where no surface is
#define ENVIRONMENT_LOOKUP_ONLY 1
#include "lib/environment.glsl"
#endif

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 direct = texelFetch(uDirect, pixel, 0);
    float coverage = clamp(direct.a, 0.0, 1.0);
#if COMPOSE_ENVIRONMENT
    vec3 background = lookUpEnvironment(normalize(computeEyeToNear(gl_FragCoord.xy)));
#else
    vec3 background = frame.backgroundRadiance;
#endif
    vec3 radiance = background * (1.0 - coverage);
    if (coverage > 0.0) radiance += direct.rgb + texelFetch(uIndirect, pixel, 0).rgb * coverage;
#if COMPOSE_EMISSION // a scene with an emitter (ComposePass)
    // This frame's emission where this frame sees a surface (GBufferPass clears it to 0 where
    // none is).
    radiance += texelFetch(uEmission, pixel, 0).rgb;
#endif
    outRadiance = vec4(radiance, 1.0);
}
