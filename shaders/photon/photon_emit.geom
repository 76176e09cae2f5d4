// Photon emission, geometry stage: warps the grid point through the light view's importance map
// (lib/importance.glsl), reads the light camera's G-buffer there, gives the photon the power of
// the part of the view it stands for (intensity x falloff x solid angle, or irradiance x area for
// the sun, divided by the map's pdf), makes the first bounce by Russian roulette (on the albedo,
// or with first_bounce weighted among the lobes alone) and writes the surviving photon to the
// bounce buffer through transform feedback. Nothing is rasterised.
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/light_gbuffer.glsl"
#include "lib/lights.glsl"
#include "lib/importance.glsl"
#include "lib/photon_lights.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"

layout(points) in;
layout(points, max_vertices = 1) out;

layout(std140, binding = kBindingPassParams) uniform EmitParamsBlock { EmitParams params; };

flat in uint vGridIndex[];

out vec4 outPositionDistance;
out vec4 outDirectionDensity;
out vec4 outPower;

void main() {
    uint index = vGridIndex[0];
    int resolution = int(params.lightResolutionPx); // light G-buffer size (texels)
    uvec2 cell = uvec2(index % params.gridPhotons.x, index / params.gridPhotons.x);
    // The grid point, warped to where the importance map sends it; the photon stands for
    // 1 / (count x pdf) of the view's unit square.
    float pdf;
    vec2 jitter = computeGridJitter(params.lightView, params.seed);
    vec2 uv = warpByImportance(params.lightView, frame.lightViewCount, (vec2(cell) + jitter) / vec2(params.gridPhotons), pdf);
    if (!(pdf > 0.0)) return;
    float share = 1.0 / (float(params.gridPhotons.x * params.gridPhotons.y) * pdf);
    ivec2 texel = min(ivec2(uv * float(resolution)), ivec2(resolution - 1));
    ivec3 at = ivec3(texel, int(params.lightView));
    vec4 position = texelFetch(uLightPosition, at, 0);
    if (position.w < 0.5) return; // the light sees nothing there

    GpuLightView view = lightViews[params.lightView];
    GpuLight light = lights[view.info.x];
    vec3 axis = view.axisTexel.xyz;
    vec3 power;
    vec3 dir;
    float travelled;
    if (view.info.y == 1u) {
        // Orthographic (sun): the view spans texelSize * resolution metres. Travel counts from
        // the first hit (the thesis, 5.2.1.a), not from a plane that depends on the scene.
        float widthM = view.axisTexel.w * float(resolution);
        power = light.power.rgb * (widthM * widthM * share);
        dir = axis;
        travelled = 0.0;
    } else {
        // Perspective: the image plane at unit distance spans [-t, t]^2, t = tan(fov / 2); the
        // solid angle per unit of the view's square is (2t)^2 / (1 + x^2 + y^2)^(3/2).
        float t = 0.5 * view.axisTexel.w * float(resolution);
        float solidAngle = 4.0 * t * t * computePlaneSolidAngleDensity((uv * 2.0 - 1.0) * t) * share;
        vec3 toSurface = position.xyz - view.originAxis.xyz;
        travelled = length(toSurface);
        dir = toSurface / travelled;
        float falloff = 1.0;
        if (light.views.z == kLightSpot) {
            falloff = computeSpotFalloffCos(dot(dir, light.directionCos.xyz), light.power.w,
                                         light.directionCos.w);
        }
        power = light.power.rgb * (falloff * solidAngle);
    }
    if (all(equal(power, vec3(0.0)))) return;

    vec4 normal = texelFetch(uLightNormal, at, 0);
    vec3 diffuse = texelFetch(uLightDiffuse, at, 0).rgb;
    vec4 specular = texelFetch(uLightSpecular, at, 0);
    vec4 transmissive = texelFetch(uLightTransmissive, at, 0);
    uint photon = params.firstPhoton + index;
    vec3 numbers;
    if (params.rngGenerator == kRngSobol) {
        // The cell's place on the Z-order curve indexes the sequence; the view and frame seed
        // the scrambling.
        uint scramble = seedRandom(params.lightView, kSobolScrambleSlot, params.seed);
        numbers = computeSobolNumbers(computeZOrder(cell), scramble);
    } else {
        uint rng = seedRandom(photon, 0u, params.seed);
        numbers.x = nextRandom(rng, params.rngGenerator);
        numbers.y = nextRandom(rng, params.rngGenerator);
        numbers.z = nextRandom(rng, params.rngGenerator);
    }
    // first_bounce weighted: the lobes' probabilities scaled to sum to 1 (scatterSurfaceWith's
    // selectScale), so the photon bounces wherever the surface reflects.
    float albedo = computeLobeAlbedo(diffuse, specular, transmissive);
    if (!(albedo > 0.0)) return;
    float selectScale = params.firstBounce == kFirstBounceWeighted ? 1.0 / albedo : 1.0;
    uint event = scatterSurfaceWith(dir, power, normal.xyz, diffuse, specular, transmissive,
                                    normal.w > 0.0, numbers, selectScale);
    if (event == kScatterAbsorbed) return;

    outPositionDistance = vec4(position.xyz, travelled);
    outDirectionDensity = vec4(dir, updatePathDensity(1.0, event, specular.w));
    outPower = vec4(power, uintBitsToFloat(photon));
    countPhoton(view.info.x, 0);
    EmitVertex();
    EndPrimitive();
}
