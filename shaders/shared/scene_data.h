// Scene data as the GPU sees it (std430 storage buffers), and the binding points of every pass.
// Included by C++ (app/render) and by GLSL through the shader loader.
#ifndef ISPM_SCENE_DATA_H
#define ISPM_SCENE_DATA_H

#include "host_device.h"

ISPM_NAMESPACE_BEGIN

// Reflectances and emission of one material; w components carry the scalars.
struct GpuMaterial {
    vec4 diffuse;      // rgb reflectance, w = base colour texture's layer + 1 in the scene's
                       // texture array (0: none; exact in float), its RGB multiplies rgb
    vec4 specular;     // rgb reflectance, w = Phong exponent
    vec4 transmissive; // rgb transmittance, w = index of refraction
    vec4 emission;     // rgb radiance W/(m^2 sr), w = 1: both sides emit (else the side the
                       // winding faces)
    vec4 surface;      // x = alpha cutoff: a point whose base colour texture's alpha (1 without
                       // a texture) is below it is cut out (0: opaque; Material::alphaCutoff),
                       // y = 1 if the file called it double-sided (every surface is two-sided),
                       // z = the normal map's layer + 1 in the scene's normal map array (0:
                       // none; exact in float), w = its scale (glTF normalTexture.scale)
};
ISPM_STATIC_ASSERT_SIZE(GpuMaterial, 80);

// One placed mesh: its triangles are triangles[firstTriangle .. firstTriangle + triangleCount).
// Normals transform by transpose(mat3(objectFromWorld)).
struct GpuInstance {
    mat4 worldFromObject;
    mat4 objectFromWorld;
    uvec4 range; // x = firstTriangle, y = triangleCount, z = bottom-level BVH root node,
                 // w = kInstanceAlphaTested if some triangle's material is alpha tested (rays
                 // read its texture at their hits), else 0
};
ISPM_STATIC_ASSERT_SIZE(GpuInstance, 144);
ISPM_CONST uint kInstanceAlphaTested = 1u;

ISPM_CONST uint kLightPoint = 0u;
ISPM_CONST uint kLightSpot = 1u;
ISPM_CONST uint kLightSun = 2u;

// Spot falloff S from the cosine of the angle to the axis: 1 inside the inner cone, 0 outside
// the outer, smoothstep in cos space between; equal cones make a hard edge, lit up to and
// including the boundary. Written once for the renderer's shaders and the CPU (photon budgets).
ISPM_INLINE float computeSpotFalloffCos(float cosAngle, float cosInner, float cosOuter) {
    if (cosInner <= cosOuter) return cosAngle >= cosOuter ? 1.0f : 0.0f;
    float s = clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    return s * s * (3.0f - 2.0f * s);
}

struct GpuLight {
    vec4 position;     // xyz position (point, spot), w unused
    vec4 directionCos; // xyz unit axis (spot) or travel direction (sun), w = cos(outer)
    vec4 power;        // rgb intensity W/sr (point, spot) or irradiance W/m^2 (sun), w = cos(inner)
    uvec4 views;       // x = first light view, y = view count (6 for a point light), z = type
                       // (kLight*),
                       // w = the sun's fitted shadow-only view + 1 (0: none)
};
ISPM_STATIC_ASSERT_SIZE(GpuLight, 64);

// One light camera (a layer of the light G-buffer array).
struct GpuLightView {
    mat4 clipFromWorld;
    vec4 originAxis; // xyz: eye (perspective) or a point on the near plane (ortho)
    vec4 axisTexel;  // xyz: unit view axis; w: texel size per metre of depth (perspective,
                     // 2 tan(fov/2) / res) or texel size in metres (ortho)
    uvec4 info;      // x = light index, y = 1 if orthographic
};
ISPM_STATIC_ASSERT_SIZE(GpuLightView, 112);

// Binding points (storage buffers).
ISPM_CONST int kBindingPositions = 0;  // vec4 per vertex, object space
ISPM_CONST int kBindingTriangles = 1;  // uvec4 (i0, i1, i2, material)
ISPM_CONST int kBindingInstances = 2;  // GpuInstance
ISPM_CONST int kBindingMaterials = 3;  // GpuMaterial
ISPM_CONST int kBindingLights = 4;     // GpuLight
ISPM_CONST int kBindingLightViews = 5; // GpuLightView
ISPM_CONST int kBindingExposure = 6;   // tone-map statistics
// mat4 per instance: its worldFromObject when the last frame was drawn (AccumulatePass
// reprojects the history of moving objects with it).
ISPM_CONST int kBindingPreviousTransforms = 21;
// GpuVertexAttributes per vertex (as kBindingPositions). One buffer for all: the photon tracer,
// which reads them all, is at llvmpipe's 16 storage blocks per compute shader.
ISPM_CONST int kBindingVertexAttributes = 34; // after the disc list (photon_data.h)
ISPM_CONST float kNoShadingNormal = 2.0f;     // outside the octahedral square [-1, 1]^2

// What a vertex carries besides its position (docs/design.md "Shading normals", "Normal maps").
struct GpuVertexAttributes {
    vec2 texcoord; // u right and v down the image (zero for meshes without textures)
    vec2 normal;   // the object-space unit shading normal (encodeOctahedral), or x =
                   // kNoShadingNormal where the mesh gives none (a triangle with such a corner
                   // is flat-shaded)
    vec4 tangent;  // xyz the object-space unit tangent along +u, w the handedness (+-1: the
                   // bitangent, up the image, is w cross(normal, tangent)); w = 0: none (a
                   // triangle with such a corner takes no normal map)
};
ISPM_STATIC_ASSERT_SIZE(GpuVertexAttributes, 32);

// A unit vector in two numbers in [-1, 1]: its octahedral map (Cigolle et al. 2014, "A Survey
// of Efficient Representations for Independent Unit Vectors"), exact to float's rounding.
ISPM_INLINE vec2 encodeOctahedral(vec3 n) {
    vec2 p = vec2(n.x, n.y) * (1.0f / (abs(n.x) + abs(n.y) + abs(n.z)));
    if (n.z >= 0.0f) return p;
    return vec2((1.0f - abs(p.y)) * (p.x >= 0.0f ? 1.0f : -1.0f),
                (1.0f - abs(p.x)) * (p.y >= 0.0f ? 1.0f : -1.0f));
}

// The vector encodeOctahedral encoded, not unit length (callers normalise, after interpolating).
ISPM_INLINE vec3 decodeOctahedral(vec2 e) {
    vec3 n = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    float fold = max(-n.z, 0.0f);
    n.x += n.x >= 0.0f ? -fold : fold;
    n.y += n.y >= 0.0f ? -fold : fold;
    return n;
}
// 7..10: the BVH (shared/bvh_data.h); 11..20: the photon and importance buffers
// (shared/photon_data.h, shared/importance_data.h)

// Binding points (uniform buffers).
ISPM_CONST int kBindingFrameConstants = 0;
// 1: the importance passes' parameters (shared/importance_data.h).
// The running pass's own parameters: each pass uploads its block (a struct in shared/, std140)
// and binds it here before it draws or dispatches.
ISPM_CONST int kBindingPassParams = 2;

// Texture units.
ISPM_CONST int kUnitGBufferFirst = 0;      // viewer G-buffer channels, in table order
ISPM_CONST int kUnitLightGBufferFirst = 8; // light G-buffer channels (2D arrays), in table order
ISPM_CONST int kUnitDirect = 16;
ISPM_CONST int kUnitIndirect = 17;
ISPM_CONST int kUnitHdr = 18;
ISPM_CONST int kUnitFilterSource = 19; // the denoise pass's input, one iteration to the next
// AccumulatePass: the averages over earlier frames, their lengths, and the viewer G-buffer's
// position and normal they were drawn on.
ISPM_CONST int kUnitHistoryDirect = 20;
ISPM_CONST int kUnitHistoryIndirect = 21;
ISPM_CONST int kUnitHistoryLength = 22;
ISPM_CONST int kUnitHistoryPosition = 23;
ISPM_CONST int kUnitHistoryNormal = 24;
// The scene's colour textures: one sRGB 2D array, a layer per texture (GpuMaterial::diffuse.w).
ISPM_CONST int kUnitCaustics = 29; // the caustic photons' splats, at the image's size (upsample)
// The filter guide (denoise/filter_input.frag): the surface each splat buffer pixel stands for.
ISPM_CONST int kUnitFilterGuide = 30;
ISPM_CONST int kUnitSceneTextures = 28; // after the post passes' 25..27 (post_data.h)
// The scene's normal maps: one linear (not sRGB) 2D array, a layer per map
// (GpuMaterial::surface.z).
ISPM_CONST int kUnitSceneNormalMaps = 31;

// Per-frame values every pass may read (std140).
struct FrameConstants {
    mat4 clipFromWorld;
    mat4 worldFromClip;
    // Clip to the world-space offset from the eye: worldFromClip without the camera's position,
    // so a ray through the image is exact however far the eye is from the origin and however
    // near its near plane (edge_shade.comp; the near plane can lie 1e-5 of the far plane away).
    mat4 eyeOffsetFromClip;
    vec3 cameraPosW;         // the eye
    uint lightCount;         // the scene's lights
    vec3 backgroundRadiance; // W/(m^2 sr) where no surface is
    uint lightViewCount;     // light cameras (layers of the light G-buffer)
    vec2 imageSizePx;        // width, height
    vec2 inverseImageSizePx; // 1 / width, 1 / height
    uint seed;               // this frame's random seed
    uint tonemapOperator;    // kTonemap*
    float shadowBiasTexels;  // shadow map depth bias
    float lightResolutionPx; // light G-buffer size (texels a side)
    float adaptationWeight;  // eye adaptation's weight this frame (1: the derived white point at
                             // once)
    float exposureScale;     // 2^exposure stops
    float inverseGamma;      // 1 / gamma
    float luminanceMax;      // white point W/(m^2 sr) (<= 0: derived)
    // The Phong exponent from which the specular pass traces a viewer pixel's lobe as a mirror
    // ray (the splats then shade only its diffuse lobe); 0: nothing traced (specular_depth 0).
    float specularTraceMinExponent;
    // Emitting triangles (shared/emitter_data.h, kBindingEmitters): their count (0: none) and
    // the sum of their sampling weights (W).
    uint emitterCount;
    float emitterWeight;
    // Samples of the emitters per viewer pixel (setting area_samples).
    uint areaSamples;
};
ISPM_STATIC_ASSERT_SIZE(FrameConstants, 288);

// Parameters of accumulate.frag (std140, at kBindingPassParams).
struct AccumulateParams {
    mat4 previousClipFromWorld; // the last frame's camera, for reprojection
    float directWeight;         // this frame's direct light's weight (1 / frames)
    float historyCapFrames;     // cap on a pixel's history length (0: no history)
    uint moved;                 // 1: the view or objects moved (reproject)
    uint padding0;
};
ISPM_STATIC_ASSERT_SIZE(AccumulateParams, 80);

// How direct light finds its shadows (setting shadows, FrameSettings::shadows): the light views'
// shadow maps (the thesis's) or a ray to the light through the BVH from every pixel.
ISPM_CONST uint kShadowsMap = 0u;
ISPM_CONST uint kShadowsRay = 1u;

// Parameters of one draw of direct.frag (std140, at kBindingPassParams; the draws are bound by
// range). A light that reaches every direction is shaded over the whole image, in draws of up to
// kDirectLightsPerDraw; a spot light over the pixels its cone's box covers (computeLitBounds), in
// a draw of its own. Only the first draw writes coverage; the others add.
ISPM_CONST uint kDirectLightsPerDraw = 60u;
struct DirectParams {
    uint lightCount; // lights in this draw
    uint firstDraw;  // 1: the first draw (alpha = coverage)
    float rayFloorM; // the ray offset floor (GpuScene::getRayEpsilon: shadows ray)
    uint padding0;
    uvec4 lights[kDirectLightsPerDraw / 4u]; // indices into the scene's lights, four a uvec4
};
ISPM_STATIC_ASSERT_SIZE(DirectParams, 256);

// Anti-aliased direct light (setting edge_samples, DirectPass): edge_find.comp lists the pixels
// at silhouettes, creases and edges of the light (a shadow's, a spot cone's), where one sample at
// the pixel's centre is not the pixel's average; edge_shade.comp shades each listed pixel again
// from samples spread over its area and writes their mean (alpha: the share that hit a surface).
ISPM_CONST int kBindingDirectEdges = 29; // DirectEdgeHeader, then one uint per listed pixel
ISPM_CONST int kImageDirect = 0;         // the direct light (rgba32f), rewritten at edges
ISPM_CONST uint kDirectEdgeGroupSize = 64u;
// edge_shade.comp shades a listed pixel with this many invocations (its samples dealt out among
// them, their sums added in shared memory): rays through one pixel run alike, side by side.
ISPM_CONST uint kDirectEdgeLanes = 8u;
ISPM_CONST uint kDirectEdgePixelsPerGroup = kDirectEdgeGroupSize / kDirectEdgeLanes;
ISPM_CONST float kDirectEdgeContrast = 0.3f; // bend of the light, as a share of the brightest
ISPM_CONST float kDirectEdgeCos = 0.95f;     // neighbours' normals apart by more: a crease
// A listed pixel's need: the spread of the direct light over it and its eight neighbours over
// sqrt(its own light^2 + kRelMseEpsilon), per channel, the largest. The error of an edge's
// coverage from N stratified samples falls as N^-1.5, and rel MSE divides it by that same
// denominator, so a pixel of low need spends its rays for little: below kDirectEdgeFullNeed it
// takes half the samples (expected rel MSE at most 2^1.5 that of a full pixel at the threshold),
// below kDirectEdgeHalfNeed a quarter (8 / 9 of it). The background counts with its radiance.
ISPM_CONST float kDirectEdgeFullNeed = 3.0f;
ISPM_CONST float kDirectEdgeHalfNeed = 1.0f;
ISPM_CONST float kDirectEdgeNeedEpsilon = 0.01f; // the rel MSE's epsilon (image/metrics.h)
ISPM_CONST uint kDirectEdgeHalvingShift = 30u;   // a listed pixel: index | halvings << shift
struct DirectEdgeHeader {
    uint groupsX; // edge_shade.comp's indirect dispatch: ceil(pixels / kDirectEdgePixelsPerGroup)
    uint groupsY; // 1
    uint groupsZ; // 1
    uint pixels;  // pixels listed, each y * width + x | halvings << kDirectEdgeHalvingShift
};
ISPM_STATIC_ASSERT_SIZE(DirectEdgeHeader, 16);

// Parameters of edge_shade.comp (std140, at kBindingPassParams).
struct DirectEdgeParams {
    uint samplesPerPixel; // samples per listed pixel (before its halvings)
    float rayFloorM;      // the ray offset floor (GpuScene::getRayEpsilon)
    uint padding0;
    uint padding1;
};
ISPM_STATIC_ASSERT_SIZE(DirectEdgeParams, 16);

// atrous.comp: work groups of kFilterGroupSide^2 pixels, writing image unit kImageFilterOutput.
ISPM_CONST uint kFilterGroupSide = 8u;
ISPM_CONST int kImageFilterOutput = 0;

// Parameters of one iteration of atrous.comp, and of upsample.frag (std140, at
// kBindingPassParams; the filter's iterations are bound by range).
struct FilterParams {
    int stepPx;   // the iteration's step (upsample: unused, its variants add the
                  // caustics)
    int modulate; // 1: multiply the output by the reflectance (the filter's last
                  // iteration at the image's size)
    int padding0;
    int pixelsPerBufferPx; // image pixels per buffer pixel along an axis
};
ISPM_STATIC_ASSERT_SIZE(FilterParams, 16);

// Parameters of one draw of gbuffer.vert and gbuffer.frag: one instance seen from one camera
// (std140, at kBindingPassParams; a view's draws are bound by range).
struct GBufferParams {
    mat4 clipFromWorld;
    // The last frame's camera, for the velocity channel (the viewer's; a light view passes its
    // own clipFromWorld, and has no velocity attachment anyway).
    mat4 previousClipFromWorld;
    vec4 eye; // w = 1: the eye's position; w = 0: the direction toward an orthographic eye
    vec2 halfTargetSizePx; // half the target's size in pixels (NDC to pixels)
    vec2 jitterMotionPx;   // change of the sub-pixel offset since the last frame (not motion:
                           // subtracted)
    uint instance;         // the instance drawn
    uint padding0;
    uint padding1;
    uint padding2;
};
ISPM_STATIC_ASSERT_SIZE(GBufferParams, 176);

// Parameters of one sample of reference.comp, the path tracer (std140, at kBindingPassParams).
struct ReferenceParams {
    uint sampleIndex;
    uint bounces;
    uint seed;
    float rayOffsetM; // ray offset off the surface a ray leaves
};
ISPM_STATIC_ASSERT_SIZE(ReferenceParams, 16);

ISPM_CONST uint kTonemapThesis = 0u;
ISPM_CONST uint kTonemapFilmic = 1u;
ISPM_CONST uint kTonemapLinear = 2u;

ISPM_NAMESPACE_END

#endif
