// What the edge-aware filter (atrous.comp) and the upsample (upsample.frag) read, one pass at
// the splat buffer's size: the splats' light divided by the reflectance where they were
// splatted (irradiance: the filters smooth it and keep texture and colour edges; the pixel's
// own reflectance multiplies it back at the end), and the guide (lib/gbuffer_filter.glsl) of
// the G-buffer pixel each buffer pixel stands for.
#include "lib/frame_constants.glsl"
#include "lib/gbuffer_filter.glsl"

layout(binding = kUnitFilterSource) uniform sampler2D uSource;

layout(std140, binding = kBindingPassParams) uniform FilterParamsBlock { FilterParams params; };

layout(location = 0) out vec4 outIrradiance;
layout(location = 1) out vec4 outGuide;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 g = getBlockGBufferPixel(pixel, params.pixelsPerBufferPx);
    vec4 position = texelFetch(uPosition, g, 0);
    outIrradiance = vec4(texelFetch(uSource, pixel, 0).rgb / getReflectance(g), 1.0);
    outGuide = position.w < 0.5 ? vec4(0.0, 0.0, 0.0, kGuideNoSurface)
                                : vec4(position.xyz, encodeGuideNormal(texelFetch(uNormal, g, 0).xyz));
}
