// What the camera sees in mirrors and glass: every viewer pixel on a mirror lobe or a
// transmissive surface traces one reflected and one refracted ray per level through the BVH,
// depth first, and adds what they see into the composed image. A hit is shaded with direct
// light (a shadow ray to each light, as the reference does) and the indirect light of the
// visible pixel it reprojects onto at the same depth; where no visible pixel shows it, an
// ambient estimate: its diffuse reflectance times the view's mean indirect light per unit
// reflectance (specular_ambient.comp, run before).
// Weights follow the reference's camera paths (reference.comp, photon_scatter.h): the Phong
// lobe's f cos / pdf at its axis, Fresnel (exact, for dielectrics) times the transmittance for
// glass, and (n_i / n_t)^2 on radiance across a refraction. What a pixel sees is written to
// uSpecularLight, with the spread in pixels of a glossy lobe's ray in alpha (0 for glass and
// untraced pixels); specular_filter.comp blurs it by that spread and adds it to the image.
#include "lib/scene_buffers.glsl"
// Before bvh.glsl, for its computeHitShadingNormal.
#include "lib/vertex_attributes.glsl"
#include "lib/scene_textures.glsl"
#include "lib/frame_constants.glsl"
#include "lib/bvh.glsl"
#include "lib/brdf.glsl"
#include "lib/lights.glsl"
#define SHADOW_RAYS 1 // shadow maps see only what light cameras see
#include "lib/direct_light.glsl"
#include "lib/emitters.glsl"
#include "lib/environment.glsl"
#include "shared/specular_data.h"

#include "lib/viewer_gbuffer.glsl"
layout(binding = kUnitIndirect) uniform sampler2D uIndirect;

layout(local_size_x = kSpecularGroupSize, local_size_y = kSpecularGroupSize) in;
layout(binding = 0, rgba32f) writeonly uniform image2D uSpecularLight;
layout(binding = kSpecularAmbientImage, rgba32f) readonly uniform image2D uAmbient;

layout(std140, binding = kBindingPassParams) uniform SpecularParamsBlock { SpecularParams params; };

// A ray whose every channel weighs less than this adds nothing visible: it is not traced.
const float kMinRayWeight = 1e-4;

struct PendingRay {
    vec3 origin;
    vec3 dir;
    vec3 weight;
    uint level; // 1 for the rays leaving the visible surface
};

PendingRay gStack[kMaxSpecularDepth + 1u];
uint gTop = 0u;

void pushRay(vec3 position, vec3 n, vec3 dir, vec3 weight, uint level, float offset,
             uint event) {
    if (max(weight.r, max(weight.g, weight.b)) < kMinRayWeight) return;
    if (!isScatterOnGeometricSide(event, dir, n)) return; // a shading normal's ray across

    // Leave on the side the new direction points to (refraction crosses the surface).
    vec3 origin = position + (dot(dir, n) >= 0.0 ? n : -n) * offset;
    gStack[gTop++] = PendingRay(origin, dir, weight, level);
}

// The rays a surface at `position` sends on for a ray along `dir`: n (geometric) faces where
// `dir` came from and decides the sides, `shading` (on n's side) reflects and refracts,
// `frontFace` says whether that is the geometric front (for the index of refraction).
void scatterRays(vec3 position, vec3 n, vec3 shading, bool frontFace, vec3 dir, vec3 diffuse,
                 vec4 specular, vec4 transmissive, vec3 weight, uint level) {
    float cosIn = clamp(-dot(dir, shading), 0.0, 1.0);
    float offset = computeRayOffset(position, params.rayFloorM);
    vec3 reflected = vec3(0.0);
    if (isMirrorLobe(specular)) reflected += computeMirrorWeight(diffuse, specular, cosIn);
    if (isTransmissive(transmissive)) {
        float eta = frontFace ? 1.0 / transmissive.w : transmissive.w;
        float fresnel = computeFresnel(cosIn, eta);
        reflected += transmissive.rgb * fresnel;
        if (fresnel < 1.0) {
            float sin2T = eta * eta * (1.0 - cosIn * cosIn);
            vec3 refracted =
                normalize(dir * eta + shading * (eta * cosIn - sqrt(1.0 - sin2T)));
            pushRay(position, n, refracted,
                    weight * transmissive.rgb * ((1.0 - fresnel) *
                                                 computeRefractedRadianceScale(frontFace, transmissive.w)),
                    level, offset, kScatterRefract);
        }
    }
    pushRay(position, n, reflect(dir, shading), weight * reflected, level, offset,
            kScatterReflect);
}

// The indirect light of a hit: that of the visible pixel it projects onto when that pixel shows
// the same point (its distance from the eye alike), else the ambient estimate.
vec3 lookUpIndirect(vec3 position, vec3 diffuse) {
    vec3 ambient = diffuse * imageLoad(uAmbient, ivec2(0)).rgb;
    ivec2 pixel;
    if (!findViewerPixel(position, pixel)) return ambient;
    vec4 visible = texelFetch(uPosition, pixel, 0);
    if (visible.w < 0.5) return ambient;
    float hitDistance = distance(position, frame.cameraPosW);
    float visibleDistance = distance(visible.xyz, frame.cameraPosW);
    if (abs(hitDistance - visibleDistance) > params.reprojectionTolerance * hitDistance) return ambient;
    return texelFetch(uIndirect, pixel, 0).rgb;
}

// A glossy lobe's mirror ray, hit `t` away from a surface `eyeDistance` from the eye, stands for
// rays spread by 1 / sqrt(e) radians per axis (cos^e ~ exp(-e a^2 / 2)): t / sqrt(e) across
// at the hit, seen from the eye along the unfolded path, in pixels (params.pixelAngleRad: a
// pixel's angle).
float computeGlossySpread(float exponent, float t, float eyeDistance) {
    return t * inversesqrt(exponent) / ((eyeDistance + t) * params.pixelAngleRad);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.imageSizePx)))) return;
    imageStore(uSpecularLight, pixel, vec4(0.0)); // what a pixel that traces nothing adds
    vec4 position = texelFetch(uPosition, pixel, 0);
    if (position.w < 0.5) return;
    vec4 specular = texelFetch(uSpecular, pixel, 0);
    vec4 transmissive = texelFetch(uTransmissive, pixel, 0);
    if (!isMirrorLobe(specular) && !isTransmissive(transmissive)) return; // left as composed
    // A glossy surface (not glass) sends one ray from the pixel: the first popped.
    bool glossy = !isTransmissive(transmissive);
    float spread = 0.0;
    vec4 normal = texelFetch(uNormal, pixel, 0); // faces the eye; w: +1 on the front face
    vec3 dir = normalize(position.xyz - frame.cameraPosW);
    uint levels = params.levels;
    gTop = 0u;
    // The G-buffer holds the shading normal alone (gbuffer.frag): it decides the sides too.
    scatterRays(position.xyz, normal.xyz, normal.xyz, normal.w > 0.0, dir, texelFetch(uDiffuse, pixel, 0).rgb,
                specular, transmissive, vec3(1.0), 1u);
    vec3 radiance = vec3(0.0);
    uvec3 emitterSeeds = computeEmitterSeeds(uint(pixel.y) * uint(frame.imageSizePx.x) + uint(pixel.x),
                                             kEmitterSeedSlot);
    while (gTop > 0u) {
        PendingRay ray = gStack[--gTop];
        RayHit hit;
        if (!traceRay(ray.origin, ray.dir, kNoHitDistance, hit)) {
            // Mirrors and glass show the environment (the background shows nowhere but in the
            // camera's own image).
            if (hasEnvironment()) radiance += ray.weight * lookUpEnvironment(ray.dir);
            continue;
        }
        if (glossy && ray.level == 1u) {
            spread = computeGlossySpread(specular.w, hit.t,
                                         distance(position.xyz, frame.cameraPosW));
        }
        vec3 hitPosition = ray.origin + ray.dir * hit.t;
        vec3 geometric = computeHitNormal(hit);
        bool frontFace = dot(geometric, ray.dir) < 0.0;
        vec3 n = frontFace ? geometric : -geometric;
        vec3 shading = computeHitShadingNormal(hit, n);
        GpuMaterial m = materials[triangles[hit.triangle].w];
        // The hit's own reflectance, its texture's included (as the reference reads it).
        vec3 diffuse = getHitDiffuse(m, hit.triangle, hit.barycentric);
        // Direct light with a shadow ray per light (glass blocks them, as in the reference).
        vec3 direct = computeShadedDirectRadiance(hitPosition, n, shading, diffuse, m.specular,
                                                  -ray.dir, params.rayFloorM);
        // The emitters' light at the hit from area_samples points, and what an emitter shows.
        direct += computeEmitterRadiance(hitPosition, n, shading, diffuse, m.specular, -ray.dir,
                                         params.rayFloorM, gTop * frame.areaSamples,
                                         frame.areaSamples, emitterSeeds);
        direct += computeEmittedRadiance(m.emission, -dot(geometric, ray.dir));
        direct += computeEnvironmentRadiance(hitPosition, n, shading, diffuse, m.specular,
                                             -ray.dir, params.rayFloorM, gTop * frame.areaSamples,
                                             frame.areaSamples, emitterSeeds.zxy);
        radiance += ray.weight * (direct + lookUpIndirect(hitPosition, diffuse));
        if (ray.level < levels) {
            scatterRays(hitPosition, n, shading, frontFace, ray.dir, diffuse, m.specular, m.transmissive,
                        ray.weight, ray.level + 1u);
        }
    }
    // A glossy pixel is marked (alpha above 0) even when its spread is tiny: the filter reads
    // only marked pixels as taps.
    imageStore(uSpecularLight, pixel, vec4(radiance, glossy ? max(spread, 1e-6) : 0.0));
}
