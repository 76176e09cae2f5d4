// Flattening of the scene model into GPU buffers.
#include "render/gpu_scene.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <span>

namespace ispm {
namespace {

std::vector<gpu::GpuInstance> buildInstances(const Scene& scene,
                                             const std::vector<uint32_t>& firstTriangle) {
    std::vector<gpu::GpuInstance> instances;
    for (const Instance& inst : scene.instances) {
        gpu::GpuInstance g{};
        g.worldFromObject = inst.worldFromObject;
        g.normalFromObject = glm::mat4(glm::inverseTranspose(glm::mat3(inst.worldFromObject)));
        g.range = glm::uvec4(firstTriangle[inst.meshIndex],
                             static_cast<uint32_t>(scene.meshes[inst.meshIndex].triangles.size()),
                             0u, 0u);
        instances.push_back(g);
    }
    return instances;
}

} // namespace

GpuScene::GpuScene(const Scene& scene, int lightResolution) : mLightResolution(lightResolution) {
    std::vector<glm::vec4> positions;
    std::vector<glm::uvec4> triangles;
    std::vector<uint32_t> firstTriangle;
    for (const Mesh& mesh : scene.meshes) {
        const auto base = static_cast<uint32_t>(positions.size());
        firstTriangle.push_back(static_cast<uint32_t>(triangles.size()));
        for (const glm::vec3& p : mesh.positions) positions.emplace_back(p, 1.0f);
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const glm::uvec3 tri = mesh.triangles[t] + base;
            triangles.emplace_back(tri, mesh.triangleMaterials[t]);
        }
    }
    std::vector<gpu::GpuMaterial> materials;
    for (const Material& m : scene.materials) {
        materials.push_back({glm::vec4(m.diffuse, 0.0f), glm::vec4(m.specular, m.phongExponent),
                             glm::vec4(m.transmissive, m.ior), glm::vec4(m.emission, 0.0f)});
    }
    mPositions = gl::Buffer::fromSpan<glm::vec4>("scene positions", positions);
    mTriangles = gl::Buffer::fromSpan<glm::uvec4>("scene triangles", triangles);
    mMaterials = gl::Buffer::fromSpan<gpu::GpuMaterial>("scene materials", materials);
    mInstances = buildInstances(scene, firstTriangle);
    mInstanceBuffer = gl::Buffer::fromSpan<gpu::GpuInstance>("scene instances", mInstances);
    uploadLights(scene);
}

void GpuScene::updateDynamic(const Scene& scene) {
    // The first triangle of each mesh, recovered from the instances that use it.
    std::vector<uint32_t> meshFirst(scene.meshes.size(), 0);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        meshFirst[scene.instances[i].meshIndex] = mInstances[i].range.x;
    }
    mInstances = buildInstances(scene, meshFirst);
    mInstanceBuffer.upload<gpu::GpuInstance>(mInstances);
    uploadLights(scene);
}

void GpuScene::uploadLights(const Scene& scene) {
    mBounds = scene.computeWorldBounds();
    mLightCameras = computeLightCameras(scene, mLightResolution);
    mLightCount = static_cast<uint32_t>(scene.lights.size());
    std::vector<gpu::GpuLight> lights;
    uint32_t firstView = 0;
    for (const Light& light : scene.lights) {
        gpu::GpuLight g{};
        const bool isSun = light.type == LightType::Sun;
        g.positionType = glm::vec4(light.position, static_cast<float>(light.type));
        g.directionCos = glm::vec4(glm::normalize(light.direction),
                                   std::cos(glm::radians(light.outerDeg)));
        g.power = glm::vec4(isSun ? light.irradiance : light.intensity,
                            std::cos(glm::radians(light.innerDeg)));
        const uint32_t viewCount = light.type == LightType::Point ? 6u : 1u;
        g.views = glm::uvec4(firstView, viewCount, 0u, 0u);
        firstView += viewCount;
        lights.push_back(g);
    }
    std::vector<gpu::GpuLightView> views;
    for (const LightCamera& cam : mLightCameras) {
        gpu::GpuLightView v{};
        v.clipFromWorld = cam.getClipFromWorld();
        v.originAxis = glm::vec4(cam.origin, 0.0f);
        v.axisTexel = glm::vec4(cam.axis, cam.isOrthographic ? cam.texelSizeM : cam.texelPerDepth);
        v.info = glm::uvec4(cam.lightIndex, cam.isOrthographic ? 1u : 0u, 0u, 0u);
        views.push_back(v);
    }
    if (mLights.getSize() == lights.size() * sizeof(gpu::GpuLight) && mLights.getId() != 0) {
        mLights.upload<gpu::GpuLight>(lights);
        mLightViews.upload<gpu::GpuLightView>(views);
    } else {
        mLights = gl::Buffer::fromSpan<gpu::GpuLight>("scene lights", lights);
        mLightViews = gl::Buffer::fromSpan<gpu::GpuLightView>("light views", views);
    }
}

void GpuScene::bind() const {
    using gl::BufferTarget;
    mPositions.bindBase(BufferTarget::Storage, gpu::kBindingPositions);
    mTriangles.bindBase(BufferTarget::Storage, gpu::kBindingTriangles);
    mInstanceBuffer.bindBase(BufferTarget::Storage, gpu::kBindingInstances);
    mMaterials.bindBase(BufferTarget::Storage, gpu::kBindingMaterials);
    mLights.bindBase(BufferTarget::Storage, gpu::kBindingLights);
    mLightViews.bindBase(BufferTarget::Storage, gpu::kBindingLightViews);
}

size_t GpuScene::getGpuBytes() const {
    return mPositions.getSize() + mTriangles.getSize() + mInstanceBuffer.getSize() +
           mMaterials.getSize() + mLights.getSize() + mLightViews.getSize();
}

} // namespace ispm
