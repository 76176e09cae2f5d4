// Flattening of the scene model into GPU buffers.
#include "render/gpu_scene.h"

#include "render/scene_texture_array.h"

#include <shared/specular_data.h>
#include <shared/surface_brdf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>

namespace ispm {
namespace {

// Camera rays on the CPU whose first hits fit the sun's shadow view (a few ms in a box city).
constexpr int kViewerSamplesPerSide = 64;

// Whether a triangle of the mesh has an alpha-tested material: only such instances make rays
// read materials and textures at their hits, so opaque scenes trace as fast as before.
bool hasAlphaTest(const Scene& scene, const Mesh& mesh) {
    return std::any_of(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(),
                       [&](uint32_t m) { return scene.materials[m].alphaCutoff > 0.0f; });
}

std::vector<gpu::GpuInstance> buildInstances(const Scene& scene, const BvhScene& bvh) {
    std::vector<gpu::GpuInstance> instances;
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes[inst.meshIndex];
        gpu::GpuInstance g{};
        g.worldFromObject = inst.worldFromObject;
        g.objectFromWorld = glm::inverse(inst.worldFromObject);
        g.range = glm::uvec4(bvh.meshFirstTriangles[inst.meshIndex],
                             static_cast<uint32_t>(mesh.triangles.size()),
                             bvh.meshBlasRoots[inst.meshIndex],
                             hasAlphaTest(scene, mesh) ? gpu::kInstanceAlphaTested : 0u);
        instances.push_back(g);
    }
    return instances;
}

std::vector<glm::mat4> getTransforms(std::span<const gpu::GpuInstance> instances) {
    std::vector<glm::mat4> transforms;
    for (const gpu::GpuInstance& inst : instances)
        transforms.push_back(inst.worldFromObject);
    return transforms;
}

// What a light emits and where, without the view indices (the fitted view follows the viewer).
bool isSameEmission(const gpu::GpuLight& a, const gpu::GpuLight& b) {
    return a.position == b.position && a.directionCos == b.directionCos && a.power == b.power &&
           a.views.z == b.views.z;
}

// Each instance's triangles' area in world space (m^2).
std::vector<double> computeInstanceAreas(const Scene& scene) {
    std::vector<double> areas;
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes[inst.meshIndex];
        double area = 0.0;
        for (const glm::uvec3& t : mesh.triangles) {
            const auto toWorld = [&](uint32_t i) {
                return glm::vec3(inst.worldFromObject * glm::vec4(mesh.positions[i], 1.0f));
            };
            const glm::vec3 p0 = toWorld(t.x);
            area += 0.5 * double(glm::length(glm::cross(toWorld(t.y) - p0, toWorld(t.z) - p0)));
        }
        areas.push_back(area);
    }
    return areas;
}

// Whether `box` has a point on the inner side of every side plane of `camera`'s view pyramid
// (any depth in front of the eye): conservative, a box that straddles two planes outside the
// pyramid's corner counts as inside.
bool meetsViewPyramid(const Aabb& box, const Camera& camera, float aspect) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float tanY = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    const float tanX = tanY * aspect;
    // Inward normals: the eye plane, then left, right, bottom, top.
    const std::array<glm::vec3, 5> normals = {
        forward, glm::normalize(right + tanX * forward), glm::normalize(-right + tanX * forward),
        glm::normalize(up + tanY * forward), glm::normalize(-up + tanY * forward)};
    for (const glm::vec3& n : normals) {
        // The box's corner furthest along n: outside when even it is behind the plane.
        const glm::vec3 corner =
            glm::mix(box.lo, box.hi, glm::vec3(glm::greaterThan(n, glm::vec3(0.0f))));
        if (glm::dot(n, corner - camera.position) < 0.0f) return false;
    }
    return true;
}

double computeViewedArea(const std::vector<double>& areas, const std::vector<Aabb>& boxes,
                         const std::optional<Camera>& viewer, float aspect) {
    double all = 0.0;
    double viewed = 0.0;
    for (size_t i = 0; i < areas.size(); ++i) {
        all += areas[i];
        if (viewer && meetsViewPyramid(boxes[i], *viewer, aspect)) viewed += areas[i];
    }
    return viewed > 0.0 ? viewed : all;
}

// The floor of the shaders' ray offsets (computeRayOffset in lib/scene_buffers.glsl, which
// grow with each point's coordinates): 1e-5 of the smallest part's size, so a scene at any
// scale, and the smallest object in a large one, keeps its rays on the right side of its
// surfaces.
float computeRayEpsilon(const Aabb& bounds, const std::vector<Aabb>& parts) {
    constexpr float kRelativeEpsilon = 1e-5f;
    float smallest = glm::length(bounds.getExtent());
    for (const Aabb& part : parts)
        smallest = std::min(smallest, glm::length(part.getExtent()));
    return kRelativeEpsilon * std::max(smallest, std::numeric_limits<float>::min());
}

} // namespace

uint32_t getGpuLightType(LightType type) {
    switch (type) {
    case LightType::Point:
        return gpu::kLightPoint;
    case LightType::Spot:
        return gpu::kLightSpot;
    case LightType::Sun:
        return gpu::kLightSun;
    }
    return gpu::kLightPoint;
}

GpuScene::GpuScene(const Scene& scene, int lightResolution) : mLightResolution(lightResolution) {
    std::vector<glm::vec4> positions;
    // One per position: texture coordinates (zero for meshes without textures), the shading
    // normal (kNoShadingNormal where a mesh gives none) and the tangent (w = 0: none).
    std::vector<gpu::GpuVertexAttributes> attributes;
    std::vector<glm::uvec4> triangles;
    for (const Mesh& mesh : scene.meshes) {
        const auto base = static_cast<uint32_t>(positions.size());
        for (const glm::vec3& p : mesh.positions)
            positions.emplace_back(p, 1.0f);
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec2 uv = v < mesh.texcoords.size() ? mesh.texcoords[v] : glm::vec2(0.0f);
            const glm::vec3 n = v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0.0f);
            const glm::vec2 encoded =
                n == glm::vec3(0.0f) ? glm::vec2(gpu::kNoShadingNormal) : gpu::encodeOctahedral(n);
            const glm::vec4 tangent = v < mesh.tangents.size() ? mesh.tangents[v] : glm::vec4(0.0f);
            attributes.push_back({uv, encoded, tangent});
        }
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const glm::uvec3 tri = mesh.triangles[t] + base;
            triangles.emplace_back(tri, mesh.triangleMaterials[t]);
        }
    }
    const SceneTextureLayers layers = assignSceneTextureLayers(scene);
    std::vector<gpu::GpuMaterial> materials;
    for (const Material& m : scene.materials) {
        // diffuse.w and surface.z: the texture's layer + 1, or 0 (shaders/shared/scene_data.h).
        const auto getLayer = [](const std::vector<int>& layerOf, uint32_t texture) {
            return texture == kNoTexture ? 0.0f : float(layerOf[texture]) + 1.0f;
        };
        materials.push_back(
            {glm::vec4(m.diffuse, getLayer(layers.colorLayer, m.diffuseTexture)),
             glm::vec4(m.specular, m.phongExponent), glm::vec4(m.transmissive, m.ior),
             glm::vec4(m.emission, m.emissionTwoSided ? 1.0f : 0.0f),
             glm::vec4(m.alphaCutoff, m.doubleSided ? 1.0f : 0.0f,
                       getLayer(layers.normalLayer, m.normalTexture), m.normalScale)});
    }
    mPositions = gl::Buffer::fromSpan<glm::vec4>("scene positions", positions);
    mTriangles = gl::Buffer::fromSpan<glm::uvec4>("scene triangles", triangles);
    mMaterials = gl::Buffer::fromSpan<gpu::GpuMaterial>("scene materials", materials);
    mVertexAttributes =
        gl::Buffer::fromSpan<gpu::GpuVertexAttributes>("scene vertex attributes", attributes);
    mTextures = buildSceneTextureArray(scene.textures, layers.colorTextures, TextureEncoding::Srgb);
    mNormalMaps =
        buildSceneTextureArray(scene.textures, layers.normalTextures, TextureEncoding::Linear);
    mHasNormalMaps = !layers.normalTextures.empty();
    mHasTextures = mHasNormalMaps ||
                   std::any_of(scene.materials.begin(), scene.materials.end(),
                               [](const Material& m) { return m.diffuseTexture != kNoTexture; });
    mHasAlphaTest = std::any_of(scene.materials.begin(), scene.materials.end(),
                                [](const Material& m) { return m.alphaCutoff > 0.0f; });
    mHasSpecularLobes = std::any_of(materials.begin(), materials.end(), [](const auto& m) {
        return gpu::hasSpecularLobe(glm::vec3(m.specular));
    });
    mHasTransmissive = std::any_of(materials.begin(), materials.end(), [](const auto& m) {
        return gpu::isTransmissive(m.transmissive);
    });
    mHasTracedSpecular = mHasTransmissive ||
                         std::any_of(materials.begin(), materials.end(),
                                     [](const auto& m) { return gpu::isMirrorLobe(m.specular); });
    mHasEmission = std::any_of(materials.begin(), materials.end(), [](const auto& m) {
        return glm::vec3(m.emission) != glm::vec3(0.0f);
    });
    mBvh = buildSceneBvh(scene);
    mBlasNodes = gl::Buffer::fromSpan<gpu::GpuBvhNode>("bvh bottom-level nodes", mBvh.blasNodes);
    mBlasOrder = gl::Buffer::fromSpan<uint32_t>("bvh triangle order", mBvh.blasTriangleOrder);
    mInstances = buildInstances(scene, mBvh);
    mInstanceBuffer = gl::Buffer::fromSpan<gpu::GpuInstance>("scene instances", mInstances);
    const std::vector<glm::mat4> transforms = getTransforms(mInstances);
    mPreviousTransforms =
        gl::Buffer::fromSpan<glm::mat4>("previous instance transforms", transforms);
    mInstanceAreasM2 = computeInstanceAreas(scene);
    uploadTopLevel();
    uploadLights(scene);
    uploadEmitters(scene);
    const gpu::GpuEnvironment environment = makeGpuEnvironment(scene.environment);
    mEnvironmentMean = computeEnvironmentMean(scene.environment);
    mEnvironment =
        gl::Buffer::fromSpan<gpu::GpuEnvironment>("scene environment", std::span(&environment, 1));
    if (scene.environment.type == EnvironmentType::Image) {
        const EnvironmentImage& image = *scene.environment.image;
        mEnvironmentImage = gl::Texture::create2D("environment image", gl::Format::RGBA32F,
                                                  image.width, image.height + 1);
        mEnvironmentImage.uploadRgba(packEnvironmentTexels(image));
    }
}

void GpuScene::uploadEmitters(const Scene& scene) {
    if (mHasEmission) mEmitters = collectEmitters(scene);
    std::vector<gpu::GpuEmitter> rows;
    rows.reserve(mEmitters.triangles.size());
    double cumulative = 0.0;
    for (size_t g = 0; g < mEmitters.groups.size(); ++g) {
        const EmitterGroup& group = mEmitters.groups[g];
        for (uint32_t i = group.first; i < group.first + group.count; ++i) {
            const EmitterTriangle& e = mEmitters.triangles[i];
            cumulative += e.weight;
            // The last row's exactly 1, so a number in [0, 1) always finds a row.
            const bool last = i + 1 == mEmitters.triangles.size();
            const float cdf = last ? 1.0f : float(cumulative / mEmitters.totalWeight);
            rows.push_back({glm::vec4(e.p0, cdf), glm::vec4(e.p1 - e.p0, float(e.areaM2)),
                            glm::vec4(e.p2 - e.p0, glm::uintBitsToFloat(uint32_t(g))),
                            glm::vec4(e.radiance, e.twoSided ? 1.0f : 0.0f)});
        }
    }
    // A buffer to bind even without emitters (the shaders that read it check
    // FrameConstants::emitterCount first).
    if (rows.empty()) rows.push_back({});
    const bool moved =
        mEmitterRows.size() == rows.size() &&
        std::memcmp(mEmitterRows.data(), rows.data(), rows.size() * sizeof(gpu::GpuEmitter)) != 0;
    if (moved) ++mLightsVersion; // light gathered from the emitters where they were is stale
    if (mEmitterBuffer.getSize() == rows.size() * sizeof(gpu::GpuEmitter) &&
        mEmitterBuffer.getId() != 0) {
        mEmitterBuffer.upload<gpu::GpuEmitter>(rows);
    } else {
        mEmitterBuffer = gl::Buffer::fromSpan<gpu::GpuEmitter>("scene emitters", rows);
    }
    mEmitterRows = std::move(rows);
}

void GpuScene::uploadTopLevel() {
    if (mTlasNodes.getSize() == mBvh.tlasNodes.size() * sizeof(gpu::GpuBvhNode) &&
        mTlasNodes.getId() != 0) {
        mTlasNodes.upload<gpu::GpuBvhNode>(mBvh.tlasNodes);
        mTlasOrder.upload<uint32_t>(mBvh.tlasInstanceOrder);
    } else {
        mTlasNodes = gl::Buffer::fromSpan<gpu::GpuBvhNode>("bvh top-level nodes", mBvh.tlasNodes);
        mTlasOrder = gl::Buffer::fromSpan<uint32_t>("bvh instance order", mBvh.tlasInstanceOrder);
    }
}

void GpuScene::updateDynamic(const Scene& scene) {
    // Bottom levels stay; the top level follows the instances' new transforms.
    rebuildTopLevel(mBvh, scene);
    uploadTopLevel();
    mInstances = buildInstances(scene, mBvh);
    mInstanceBuffer.upload<gpu::GpuInstance>(mInstances);
    mTransformsMoved = true;
    mInstanceAreasM2 = computeInstanceAreas(scene); // scaled instances change them
    uploadLights(scene);
    uploadEmitters(scene); // emitters move with their instances
}

void GpuScene::uploadLights(const Scene& scene) {
    mInstanceBounds = scene.computeInstanceBounds();
    mBounds = computeUnion(mInstanceBounds);
    mRayEpsilon = computeRayEpsilon(mBounds, mInstanceBounds);
    mSurfaceAreaM2 = computeViewedArea(mInstanceAreasM2, mInstanceBounds, mViewer, mViewerAspect);
    mLightCameras = computeLightCameras(scene, mLightResolution);
    // Shadow-only views after every light's own, so the emitting views keep their indices.
    std::vector<uint32_t> fittedView(scene.lights.size(), 0u);
    if (mViewer) {
        const std::vector<glm::vec3> visible =
            sampleVisiblePoints(mBvh, scene, *mViewer, mViewerAspect, kViewerSamplesPerSide);
        const size_t emitting = mLightCameras.size();
        for (size_t v = 0; v < emitting; ++v) {
            const LightCamera sun = mLightCameras[v];
            if (!sun.isOrthographic) continue;
            if (std::optional<LightCamera> fine = fitSunView(sun, visible, mLightResolution)) {
                fittedView[sun.lightIndex] = uint32_t(mLightCameras.size()) + 1u;
                mLightCameras.push_back(*fine);
            }
        }
    }
    mLightCount = static_cast<uint32_t>(scene.lights.size());
    std::vector<gpu::GpuLight> lights;
    uint32_t firstView = 0;
    for (const Light& light : scene.lights) {
        gpu::GpuLight g{};
        const bool isSun = light.type == LightType::Sun;
        g.position = glm::vec4(light.position, 0.0f);
        g.directionCos =
            glm::vec4(glm::normalize(light.direction), std::cos(glm::radians(light.outerDeg)));
        g.power = glm::vec4(isSun ? light.irradiance : light.intensity,
                            std::cos(glm::radians(light.innerDeg)));
        const uint32_t viewCount = light.type == LightType::Point ? 6u : 1u;
        g.views = glm::uvec4(firstView, viewCount, getGpuLightType(light.type),
                             fittedView[lights.size()]);
        firstView += viewCount;
        lights.push_back(g);
    }
    if (!std::equal(lights.begin(), lights.end(), mEmitted.begin(), mEmitted.end(),
                    isSameEmission)) {
        mEmitted = lights;
        ++mLightsVersion;
    }
    if (mLights.getSize() == lights.size() * sizeof(gpu::GpuLight) && mLights.getId() != 0) {
        mLights.upload<gpu::GpuLight>(lights);
    } else {
        mLights = gl::Buffer::fromSpan<gpu::GpuLight>("scene lights", lights);
    }
    uploadLightViews();
}

glm::mat4 GpuScene::getLightClipFromWorld(size_t view) const {
    return computeClipShift(mLightJitter, glm::vec2(float(mLightResolution))) *
           mLightCameras[view].getClipFromWorld();
}

void GpuScene::setViewer(const Scene& scene, const Camera& camera, float aspect) {
    if (mViewer && isSameCamera(*mViewer, camera) && mViewerAspect == aspect) return;
    mViewer = camera;
    mViewerAspect = aspect;
    uploadLights(scene);
}

void GpuScene::setLightResolution(const Scene& scene, int resolution) {
    if (resolution == mLightResolution) return;
    mLightResolution = resolution;
    uploadLights(scene); // the cameras' texel sizes and the sun's fitted view follow it
}

void GpuScene::setLightJitter(glm::vec2 texels) {
    if (texels == mLightJitter) return;
    mLightJitter = texels;
    uploadLightViews();
}

void GpuScene::uploadLightViews() {
    std::vector<gpu::GpuLightView> views;
    std::vector<glm::mat4> projections; // as uploaded: jittered
    std::vector<glm::mat4> emitting;    // the emitting views' own, unjittered
    for (size_t i = 0; i < mLightCameras.size(); ++i) {
        const LightCamera& cam = mLightCameras[i];
        gpu::GpuLightView v{};
        v.clipFromWorld = getLightClipFromWorld(i);
        v.originAxis = glm::vec4(cam.origin, 0.0f);
        v.axisTexel = glm::vec4(cam.axis, cam.isOrthographic ? cam.texelSizeM : cam.texelPerDepth);
        v.info = glm::uvec4(cam.lightIndex, cam.isOrthographic ? 1u : 0u, 0u, 0u);
        views.push_back(v);
        projections.push_back(v.clipFromWorld);
        if (!cam.isShadowOnly) emitting.push_back(cam.getClipFromWorld());
    }
    if (projections != mUploadedViews) {
        mUploadedViews = std::move(projections);
        ++mLightViewsVersion;
    }
    if (emitting != mEmittingViews) {
        mEmittingViews = std::move(emitting);
        ++mEmittingViewsVersion;
    }
    if (mLightViews.getSize() == views.size() * sizeof(gpu::GpuLightView) &&
        mLightViews.getId() != 0) {
        mLightViews.upload<gpu::GpuLightView>(views);
    } else {
        mLightViews = gl::Buffer::fromSpan<gpu::GpuLightView>("light views", views);
    }
}

void GpuScene::keepTransformsAsPrevious() {
    if (!mTransformsMoved) return;
    mTransformsMoved = false;
    mPreviousTransforms.upload<glm::mat4>(getTransforms(mInstances));
}

std::vector<std::string> GpuScene::getSurfaceDefines() const {
    if (mHasSpecularLobes) return {};
    return {"SURFACE_SPECULAR 0"};
}

std::vector<std::string> GpuScene::getRayDefines() const {
    std::vector<std::string> defines;
    if (!mHasAlphaTest) defines.emplace_back("BVH_ALPHA_TEST 0");
    if (!mHasNormalMaps) defines.emplace_back("SCENE_NORMAL_MAPS 0");
    return defines;
}

void GpuScene::bind() const {
    using gl::BufferTarget;
    mPositions.bindBase(BufferTarget::Storage, gpu::kBindingPositions);
    mTriangles.bindBase(BufferTarget::Storage, gpu::kBindingTriangles);
    mInstanceBuffer.bindBase(BufferTarget::Storage, gpu::kBindingInstances);
    mPreviousTransforms.bindBase(BufferTarget::Storage, gpu::kBindingPreviousTransforms);
    mMaterials.bindBase(BufferTarget::Storage, gpu::kBindingMaterials);
    mVertexAttributes.bindBase(BufferTarget::Storage, gpu::kBindingVertexAttributes);
    mTextures.bindUnit(gpu::kUnitSceneTextures);
    mNormalMaps.bindUnit(gpu::kUnitSceneNormalMaps);
    mLights.bindBase(BufferTarget::Storage, gpu::kBindingLights);
    mLightViews.bindBase(BufferTarget::Storage, gpu::kBindingLightViews);
    mBlasNodes.bindBase(BufferTarget::Storage, gpu::kBindingBlasNodes);
    mBlasOrder.bindBase(BufferTarget::Storage, gpu::kBindingBlasTriangleOrder);
    mTlasNodes.bindBase(BufferTarget::Storage, gpu::kBindingTlasNodes);
    mTlasOrder.bindBase(BufferTarget::Storage, gpu::kBindingTlasInstanceOrder);
    mEmitterBuffer.bindBase(BufferTarget::Storage, gpu::kBindingEmitters);
    mEnvironment.bindBase(BufferTarget::Storage, gpu::kBindingEnvironment);
    if (mEnvironmentImage.getId() != 0) mEnvironmentImage.bindUnit(gpu::kUnitEnvironmentImage);
}

size_t GpuScene::getGpuBytes() const {
    return mPositions.getSize() + mTriangles.getSize() + mInstanceBuffer.getSize() +
           mPreviousTransforms.getSize() + mMaterials.getSize() + mLights.getSize() +
           mLightViews.getSize() + mBlasNodes.getSize() + mBlasOrder.getSize() +
           mTlasNodes.getSize() + mTlasOrder.getSize() + mVertexAttributes.getSize() +
           mEmitterBuffer.getSize() + mEnvironment.getSize() + getTextureBytes() +
           size_t(mEnvironmentImage.getWidth()) * size_t(mEnvironmentImage.getHeight()) *
               sizeof(glm::vec4);
}

size_t GpuScene::getTextureBytes() const {
    constexpr double kRgbaBytes = 4.0;
    constexpr double kMipChainFactor = 4.0 / 3.0; // 1 + 1/4 + 1/16 + ...
    return static_cast<size_t>(double(mTextures.getWidth()) * double(mTextures.getHeight()) *
                               double(mTextures.getLayers()) * kRgbaBytes * kMipChainFactor);
}

} // namespace ispm
