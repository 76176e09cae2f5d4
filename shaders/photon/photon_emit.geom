// Photon emission, geometry stage: reads the light camera's G-buffer at the grid point, gives the
// photon the power of its grid cell (intensity x falloff x cell solid angle, or irradiance x cell
// area for the sun), makes the first bounce by Russian roulette and writes the surviving photon
// to the bounce buffer through transform feedback. Nothing is rasterised.
#include "lib/scene_buffers.glsl"
#include "lib/frame_constants.glsl"
#include "lib/light_gbuffer.glsl"
#include "lib/lights.glsl"
#include "shared/photon_data.h"
#include "shared/photon_scatter.h"

layout(points) in;
layout(points, max_vertices = 1) out;

layout(location = 0) uniform uint uView;        // light view (G-buffer layer)
layout(location = 1) uniform uvec2 uGridSize;   // photons across and down the view
layout(location = 2) uniform uint uFirstPhoton; // global index of this view's first photon
layout(location = 3) uniform uvec2 uSeedMode;   // x = frame seed, y = kRng* mode
layout(location = 4) uniform int uResolution;   // light G-buffer size (texels)

flat in uint vGridIndex[];

out vec4 outPositionDistance;
out vec4 outDirectionDensity;
out vec4 outPower;

// Solid angle of the image-plane rectangle [0,x] x [0,y] at unit distance from the eye.
float computeCornerSolidAngle(float x, float y) { return atan(x * y, sqrt(1.0 + x * x + y * y)); }

// Solid angle of the image-plane cell [p0, p1] at unit distance from the eye. Large cells: the
// exact corner formula. Small cells: its four terms nearly cancel in float (absolute error
// ~1e-7 sr whatever the cell), so integrate (1 + x^2 + y^2)^(-3/2) over the cell with 3x3
// Gauss-Legendre instead, whose error falls as the cell's size to the sixth power.
const float kExactCellSize = 0.25; // image-plane units; 1e-7 / (0.25^2 cos^3) < 1e-5 relative
float computeCellSolidAngle(vec2 p0, vec2 p1) {
    vec2 size = p1 - p0;
    if (max(size.x, size.y) > kExactCellSize) {
        return abs(computeCornerSolidAngle(p1.x, p1.y) - computeCornerSolidAngle(p0.x, p1.y) -
                   computeCornerSolidAngle(p1.x, p0.y) + computeCornerSolidAngle(p0.x, p0.y));
    }
    const float nodes[3] = float[3](-0.774596669241483, 0.0, 0.774596669241483);
    const float weights[3] = float[3](0.555555555555556, 0.888888888888889, 0.555555555555556);
    vec2 centre = 0.5 * (p0 + p1);
    float sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            vec2 p = centre + 0.5 * size * vec2(nodes[i], nodes[j]);
            float r2 = 1.0 + dot(p, p);
            sum += weights[i] * weights[j] / (r2 * sqrt(r2));
        }
    }
    return sum * 0.25 * size.x * size.y;
}

void main() {
    uint index = vGridIndex[0];
    uvec2 cell = uvec2(index % uGridSize.x, index / uGridSize.x);
    vec2 cellSize = 1.0 / vec2(uGridSize);
    vec2 uv0 = vec2(cell) * cellSize;
    vec2 uv1 = uv0 + cellSize;
    vec2 uv = uv0 + 0.5 * cellSize;
    ivec2 texel = min(ivec2(uv * float(uResolution)), ivec2(uResolution - 1));
    ivec3 at = ivec3(texel, int(uView));
    vec4 position = texelFetch(uLightPosition, at, 0);
    if (position.w < 0.5) return; // the light sees nothing there

    GpuLightView view = lightViews[uView];
    GpuLight light = lights[view.info.x];
    vec3 axis = view.axisTexel.xyz;
    vec3 power;
    vec3 dir;
    float travelled;
    if (view.info.y == 1u) {
        // Orthographic (sun): the view spans texelSize * resolution metres.
        float widthM = view.axisTexel.w * float(uResolution);
        power = light.power.rgb * (widthM * cellSize.x) * (widthM * cellSize.y);
        dir = axis;
        travelled = dot(position.xyz - view.originAxis.xyz, axis);
    } else {
        // Perspective: the image plane at unit distance spans [-t, t]^2, t = tan(fov / 2).
        float t = 0.5 * view.axisTexel.w * float(uResolution);
        vec2 p0 = (uv0 * 2.0 - 1.0) * t;
        vec2 p1 = (uv1 * 2.0 - 1.0) * t;
        float solidAngle = computeCellSolidAngle(p0, p1);
        vec3 toSurface = position.xyz - view.originAxis.xyz;
        travelled = length(toSurface);
        dir = toSurface / travelled;
        float falloff = 1.0;
        if (uint(light.positionType.w + 0.5) == kLightSpot) {
            falloff = computeSpotFalloff(dot(dir, light.directionCos.xyz), light.power.w,
                                         light.directionCos.w);
        }
        power = light.power.rgb * (falloff * solidAngle);
    }
    if (all(equal(power, vec3(0.0)))) return;

    vec4 normal = texelFetch(uLightNormal, at, 0);
    vec3 diffuse = texelFetch(uLightDiffuse, at, 0).rgb;
    vec4 specular = texelFetch(uLightSpecular, at, 0);
    vec4 transmissive = texelFetch(uLightTransmissive, at, 0);
    uint photon = uFirstPhoton + index;
    uint rng = seedRandom(photon, 0u, uSeedMode.x);
    uint event = scatterPhoton(dir, power, normal.xyz, diffuse, specular, transmissive,
                               normal.w > 0.0, rng, uSeedMode.y);
    if (event == kScatterAbsorbed) return;

    outPositionDistance = vec4(position.xyz, travelled);
    outDirectionDensity = vec4(dir, updatePathDensity(1.0, event, specular.w));
    outPower = vec4(power, uintBitsToFloat(photon));
    EmitVertex();
    EndPrimitive();
}
