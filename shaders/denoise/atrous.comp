// One iteration of the edge-aware a-trous filter on the indirect light (Dammertz et al. 2010):
// a 5x5 B3-spline kernel with holes of `step` pixels, each tap weighted down where the surface
// turns (normals) or steps away from the pixel's plane (positions, in pixel footprints). It
// filters irradiance (filter_input.frag divided the splats by the reflectance) and reads the
// taps' surfaces from the guide; the last iteration multiplies by the reflectance again, unless
// an upsample to the image's resolution follows, which reads irradiance.
//
// A work group filters 8x8 pixels `step` apart (one of the step^2 lattices the image splits
// into, a block of it), so that their taps are the 12x12 lattice points round them: each is
// read from the guide and the source once, its normal decoded once, into shared memory
// (llvmpipe: 25 texel fetches and normal decodes a pixel took most of the filter's time).
#include "lib/frame_constants.glsl"
#include "lib/gbuffer_filter.glsl"

layout(local_size_x = kFilterGroupSide, local_size_y = kFilterGroupSide) in;
layout(binding = kUnitFilterSource) uniform sampler2D uSource;
layout(binding = kUnitFilterGuide) uniform sampler2D uGuide;
layout(binding = kImageFilterOutput, rgba32f) uniform writeonly image2D uOutput;

layout(std140, binding = kBindingPassParams) uniform FilterParamsBlock { FilterParams params; };

const int kApron = 2; // the kernel's reach, in steps
const int kTileSide = int(kFilterGroupSide) + 2 * kApron;
shared vec4 tilePosition[kTileSide * kTileSide]; // the guide's point; w: 1 a surface, 0 no tap
shared vec3 tileNormal[kTileSide * kTileSide];
shared vec3 tileLight[kTileSide * kTileSide];

void main() {
    int step = params.stepPx;
    ivec2 size = textureSize(uSource, 0);
    // The lattice (its offset below `step` along each axis) and the block of it.
    ivec2 group = ivec2(gl_WorkGroupID.xy);
    ivec2 lattice = group % step;
    ivec2 blockFirst = (group / step) * int(kFilterGroupSide) * step + lattice;
    ivec2 tileFirst = blockFirst - kApron * step;
    for (int i = int(gl_LocalInvocationIndex); i < kTileSide * kTileSide;
         i += int(kFilterGroupSide * kFilterGroupSide)) {
        ivec2 q = tileFirst + ivec2(i % kTileSide, i / kTileSide) * step;
        bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
        vec4 guide = inside ? texelFetch(uGuide, q, 0) : vec4(0.0, 0.0, 0.0, kGuideNoSurface);
        bool surface = guide.w != kGuideNoSurface;
        tilePosition[i] = vec4(guide.xyz, surface ? 1.0 : 0.0);
        tileNormal[i] = surface ? decodeGuideNormal(guide.w) : vec3(0.0);
        tileLight[i] = inside ? texelFetch(uSource, q, 0).rgb : vec3(0.0);
    }
    barrier();

    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 pixel = blockFirst + local * step;
    if (any(greaterThanEqual(pixel, size))) return;
    int centreAt = (local.y + kApron) * kTileSide + local.x + kApron;
    ivec2 g = getBlockGBufferPixel(pixel, params.pixelsPerBufferPx);
    vec3 filtered = tileLight[centreAt];
    if (tilePosition[centreAt].w > 0.5) {
        vec3 n = tileNormal[centreAt];
        vec3 position = tilePosition[centreAt].xyz;
        // Footprints of a filtered pixel on its surface, times the step.
        float planeScale = computePlaneScale(g, position, params.pixelsPerBufferPx) / float(step);
        const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
        vec3 sum = vec3(0.0);
        float weights = 0.0;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                int at = centreAt + dy * kTileSide + dx;
                if (tilePosition[at].w < 0.5) continue;
                float w = kB3[abs(dx)] * kB3[abs(dy)] *
                          weighSurface(tilePosition[at].xyz, tileNormal[at], n, position, planeScale);
                if (w <= 0.0) continue;
                sum += w * tileLight[at];
                weights += w;
            }
        }
        if (weights > 0.0) filtered = sum / weights;
    }
    imageStore(uOutput, pixel,
               vec4(params.modulate == 1 ? filtered * getReflectance(g) : filtered, 1.0));
}
