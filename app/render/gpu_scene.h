// The scene uploaded to storage buffers in the layouts of shaders/shared/scene_data.h: vertex
// positions, triangles with material, instances, materials, lights and light cameras. Shared by
// every pass (rasterisers pull vertices from it, the photon tracer will traverse it).
#pragma once

#include "bvh/bvh_scene.h"
#include "gl/objects.h"
#include "render/light_cameras.h"
#include "scene/emitters.h"
#include "scene/scene.h"

#include <glm/gtc/constants.hpp>

#include <shared/emitter_data.h>
#include <shared/scene_data.h>

#include <optional>
#include <string>
#include <vector>

namespace ispm {

// The shaders' kLight* of a light type.
uint32_t getGpuLightType(LightType type);

class GpuScene {
  public:
    GpuScene(const Scene& scene, int lightResolution);

    // Re-uploads instance transforms and lights (animation, viewer edits); same topology.
    void updateDynamic(const Scene& scene);

    void bind() const; // binds every buffer (scene and BVH) to its kBinding* point
    // Whether any material has a texture or a normal map (the G-buffer then draws with its
    // textured variant), and whether any has a normal map.
    bool hasTextures() const { return mHasTextures; }
    bool hasNormalMaps() const { return mHasNormalMaps; }
    // Whether any material is alpha tested (Material::alphaCutoff): the G-buffers then draw with
    // the variant that cuts its points out.
    bool hasAlphaTest() const { return mHasAlphaTest; }
    // Whether any material is a mirror-like lobe or transmissive (isMirrorLobe, isTransmissive
    // of shared/specular_data.h): the surfaces SpecularPass traces; without one it does nothing.
    bool hasTracedSpecular() const { return mHasTracedSpecular; }
    // Whether any material has a specular part (its Phong lobe and Fresnel split): without one
    // every surface is Lambertian, and the shading passes draw with SURFACE_SPECULAR 0
    // (getSurfaceDefines).
    bool hasSpecularLobes() const { return mHasSpecularLobes; }
    // Whether any material transmits light (isTransmissive), and whether any emits it.
    bool hasTransmissive() const { return mHasTransmissive; }
    bool hasEmission() const { return mHasEmission; }
    // The shader defines of the scene's reflection model: {"SURFACE_SPECULAR 0"} without
    // specular parts (lib/brdf.glsl), else none.
    std::vector<std::string> getSurfaceDefines() const;
    // The shader defines of the scene's ray tests and hits (lib/bvh.glsl): "BVH_ALPHA_TEST 0"
    // without alpha-tested materials, so that their traversal compiles without the test
    // (llvmpipe runs both sides of a branch), and "SCENE_NORMAL_MAPS 0" without normal maps
    // (computeHitShadingNormal reads no material).
    std::vector<std::string> getRayDefines() const;

    // The instances' transforms of the frame drawn last (kBindingPreviousTransforms), which
    // reproject its pixels onto objects that moved since: FrameRunner keeps them after each
    // frame it draws. A new GpuScene starts with the present ones.
    void keepTransformsAsPrevious();
    // Goes up when updateDynamic changes what a light emits or where (position, direction,
    // cones, power, type): light accumulated before is stale.
    uint64_t getLightsVersion() const { return mLightsVersion; }

    uint32_t getInstanceCount() const { return static_cast<uint32_t>(mInstances.size()); }
    const gpu::GpuInstance& getInstance(uint32_t i) const { return mInstances[i]; }
    const std::vector<LightCamera>& getLightCameras() const { return mLightCameras; }
    uint32_t getLightCount() const { return mLightCount; }
    // The emitting triangles as last uploaded (kBindingEmitters, in the table's pick order), and
    // their count (0: the scene emits from no surface).
    const Emitters& getEmitters() const { return mEmitters; }
    uint32_t getEmitterCount() const { return uint32_t(mEmitters.triangles.size()); }
    // What photons come from: the lights, then the emitter groups (the light index photons carry,
    // ResultPhoton::incoming.w, and the per-light counters).
    uint32_t getPhotonSourceCount() const {
        return mLightCount + uint32_t(mEmitters.groups.size()) + (hasEnvironment() ? 1u : 0u);
    }
    // Whether the scene has an environment (kBindingEnvironment), and the power (W, luminance)
    // it sends into the scene's bounding box, its photons' share: the mean radiance x the solid
    // angle x the box's mean outline, a quarter of its surface (exact for a constant).
    bool hasEnvironment() const { return mEnvironmentMean.solidAngleSr > 0.0; }
    double getEnvironmentPowerW() const {
        const glm::dvec3 e(mBounds.getExtent());
        const double surfaceM2 = 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
        return mEnvironmentMean.luminance * mEnvironmentMean.solidAngleSr * 0.25 * surfaceM2;
    }
    // Light camera `view`'s projection, moved by the light jitter (setLightJitter).
    glm::mat4 getLightClipFromWorld(size_t view) const;
    // Moves every light camera by `texels` of its G-buffer (accumulated frames'
    // computeShadowJitter) and re-uploads the light views when that changed.
    void setLightJitter(glm::vec2 texels);
    // The viewer the sun's shadows are fitted to (fitSunView, from the points it sees); refits
    // when the camera or the aspect changed, and with every updateDynamic.
    void setViewer(const Scene& scene, const Camera& camera, float aspect);
    // Goes up whenever a light view's projection changes (a light moved, the fit, the jitter):
    // what was aimed through the old views must be aimed again.
    uint64_t getLightViewsVersion() const { return mLightViewsVersion; }
    // Goes up when an emitting view's own projection changes (a light moved), not with the
    // sun's shadow-only view (fitted to the viewer) nor with the jitter (a fraction of a texel):
    // what the importance maps' texels stand for.
    uint64_t getEmittingViewsVersion() const { return mEmittingViewsVersion; }
    int getLightResolution() const { return mLightResolution; }
    // Re-makes the light cameras and views at `resolution` (shadow_map_size, set or derived from
    // a photon budget) from `scene` as last uploaded; geometry, instances and the BVH stay.
    void setLightResolution(const Scene& scene, int resolution);
    const Aabb& getBounds() const { return mBounds; }
    // Each instance's world box (Scene::computeInstanceBounds), kept with getBounds.
    const std::vector<Aabb>& getInstanceBounds() const { return mInstanceBounds; }
    // The area photons are spread over, for derived splat radii (m^2): of the instances whose
    // boxes meet the viewer's view pyramid (setViewer; photons go where the viewer looks), or
    // of every instance before a viewer is set or when none meets it. A huge object out of
    // view no longer widens the discs of the room in view.
    double getSurfaceArea() const { return mSurfaceAreaM2; }
    size_t getGpuBytes() const;
    const BvhScene& getBvh() const { return mBvh; }
    // The smallest distance rays step off the surface they leave (m), relative to the scene's
    // smallest part; the shaders grow it with the coordinates (computeRayOffset), so float
    // round-off of hit positions never makes a ray hit its own surface again.
    float getRayEpsilon() const { return mRayEpsilon; }

  private:
    size_t getTextureBytes() const; // the texture array with its mipmaps
    void uploadLights(const Scene& scene);
    void uploadLightViews();
    void uploadTopLevel();
    void uploadEmitters(const Scene& scene);

    std::vector<gpu::GpuInstance> mInstances;
    std::vector<LightCamera> mLightCameras;
    glm::vec2 mLightJitter{0.0f};          // texels (setLightJitter)
    std::optional<Camera> mViewer;         // setViewer
    std::vector<glm::mat4> mUploadedViews; // clipFromWorld as last uploaded
    uint64_t mLightViewsVersion = 0;
    std::vector<glm::mat4> mEmittingViews; // the emitting views' clipFromWorld, unjittered
    uint64_t mEmittingViewsVersion = 0;
    std::vector<gpu::GpuLight> mEmitted; // the lights as last uploaded, view indices cleared
    uint64_t mLightsVersion = 0;
    bool mTransformsMoved = false; // since keepTransformsAsPrevious
    float mViewerAspect = 1.0f;
    uint32_t mLightCount = 0;
    int mLightResolution = 0;
    Aabb mBounds;
    std::vector<Aabb> mInstanceBounds;
    float mRayEpsilon = 0.0f;             // with the bounds
    std::vector<double> mInstanceAreasM2; // each instance's, world space
    double mSurfaceAreaM2 = 0.0;          // getSurfaceArea, with the bounds
    gl::Buffer mPositions;
    gl::Buffer mTriangles;
    gl::Buffer mInstanceBuffer;
    gl::Buffer mPreviousTransforms;
    gl::Buffer mMaterials;
    gl::Buffer mVertexAttributes; // kBindingVertexAttributes
    gl::Texture mTextures;        // kUnitSceneTextures (scene_texture_array.h)
    gl::Texture mNormalMaps;      // kUnitSceneNormalMaps
    bool mHasTextures = false;    // a material reads a colour texture or a normal map
    bool mHasNormalMaps = false;
    bool mHasAlphaTest = false;
    bool mHasSpecularLobes = true;
    bool mHasTracedSpecular = false;
    bool mHasTransmissive = true;
    bool mHasEmission = true;
    gl::Buffer mLights;
    gl::Buffer mEnvironment;       // kBindingEnvironment
    gl::Texture mEnvironmentImage; // kUnitEnvironmentImage (an image environment's)
    EnvironmentMean mEnvironmentMean;
    Emitters mEmitters;
    std::vector<gpu::GpuEmitter> mEmitterRows; // as last uploaded
    gl::Buffer mEmitterBuffer;                 // kBindingEmitters (one unused row for none)
    gl::Buffer mLightViews;
    BvhScene mBvh;
    gl::Buffer mBlasNodes;
    gl::Buffer mBlasOrder;
    gl::Buffer mTlasNodes;
    gl::Buffer mTlasOrder;
};

} // namespace ispm
