// G-buffer resources and the scene rasteriser shared by the viewer and light-view passes.
#include "render/gbuffer.h"

#include "gl/state.h"
#include "render/gpu_scene.h"
#include "render/shader_root.h"

#include <algorithm>
#include <cassert>
#include <numeric>
#include <stdexcept>

namespace ispm {
namespace {

constexpr int kPositionChannel = 0; // the first of kChannels: a draw buffer count of 1 holds it
constexpr GBufferChannel kChannels[] = {
    {"position", "GBUFFER_POSITION", gl::Format::RGBA32F,
     "world position in metres; w = 1 + the instance's index on a surface, 0 where nothing was "
     "hit"},
    {"normal", "GBUFFER_NORMAL", gl::Format::RGBA16F,
     "unit world normal turned toward the camera; w = 1 if the camera sees the front face "
     "(counter-clockwise winding), -1 if the back"},
    {"diffuse", "GBUFFER_DIFFUSE", gl::Format::RGBA16F, "diffuse reflectance rgb"},
    {"specular", "GBUFFER_SPECULAR", gl::Format::RGBA16F,
     "specular reflectance rgb; w = Phong exponent", false, ChannelSource::SpecularLobes},
    {"transmissive", "GBUFFER_TRANSMISSIVE", gl::Format::RGBA16F,
     "transmittance rgb; w = index of refraction", false, ChannelSource::Transmissive},
    {"emission", "GBUFFER_EMISSION", gl::Format::RGBA16F, "emitted radiance rgb, W/(m^2 sr)", true,
     ChannelSource::Emission},
    {"velocity", "GBUFFER_VELOCITY", gl::Format::RG16F,
     "screen-space motion since the last frame drawn, in pixels (x right, y up): where this "
     "surface point was, moved with its instance and seen through the last frame's camera; 0 where "
     "nothing was hit (motion blur)",
     true, ChannelSource::Motion},
};

} // namespace

std::span<const GBufferChannel> getGBufferChannels() {
    return kChannels;
}

std::vector<std::string> getGBufferDefines() {
    std::vector<std::string> defines;
    for (size_t i = 0; i < std::size(kChannels); ++i) {
        defines.push_back(std::string(kChannels[i].define) + " " + std::to_string(i));
    }
    return defines;
}

GBuffer::GBuffer(std::string_view label, int width, int height, int layers, bool isArray)
    : mWidth(width), mHeight(height), mLayers(layers) {
    const std::string base(label);
    for (const GBufferChannel& c : kChannels) {
        if (isArray && c.viewerOnly) continue; // light views: the table's shared channels
        const std::string name = base + " " + std::string(c.name);
        mChannels.push_back(isArray
                                ? gl::Texture::create2DArray(name, c.format, width, height, layers)
                                : gl::Texture::create2D(name, c.format, width, height));
    }
    mDepth = isArray ? gl::Texture::create2DArray(base + " depth", gl::Format::Depth32F, width,
                                                  height, layers)
                     : gl::Texture::create2D(base + " depth", gl::Format::Depth32F, width, height);
    for (int layer = 0; layer < layers; ++layer) {
        gl::Framebuffer fb(base + " target " + std::to_string(layer));
        for (size_t i = 0; i < mChannels.size(); ++i) {
            fb.attachColor(static_cast<int>(i), mChannels[i], isArray ? layer : -1);
        }
        fb.attachDepth(mDepth, isArray ? layer : -1);
        fb.setDrawBufferCount(static_cast<int>(mChannels.size()));
        fb.checkComplete();
        mTargets.push_back(std::move(fb));
    }
}

void GBuffer::setChannelsInUse(uint32_t mask) {
    mask |= 1u << kPositionChannel; // every reader looks at position first
    const uint32_t leaving = mChannelsInUse & ~mask;
    mChannelsInUse = mask;
    for (size_t i = 0; i < mChannels.size(); ++i) {
        if (((leaving >> i) & 1u) == 0) continue;
        for (const gl::Framebuffer& fb : mTargets)
            fb.clearColor(static_cast<int>(i), glm::vec4(0.0f));
    }
}

void GBuffer::clear(int layer) const {
    const gl::Framebuffer& fb = mTargets[static_cast<size_t>(layer)];
    for (size_t i = 0; i < mChannels.size(); ++i) {
        if ((mChannelsInUse >> i) & 1u) fb.clearColor(static_cast<int>(i), glm::vec4(0.0f));
    }
    fb.clearDepth(1.0f);
}

void GBuffer::bindTarget(int layer) {
    gl::Framebuffer& fb = mTargets[static_cast<size_t>(layer)];
    // bindPositionTarget narrows the draw buffers: set them anew.
    fb.setDrawBuffers(static_cast<int>(mChannels.size()), mChannelsInUse);
    fb.bind();
}

void GBuffer::clearPositions(int layer) const {
    const gl::Framebuffer& fb = mTargets[static_cast<size_t>(layer)];
    fb.clearColor(kPositionChannel, glm::vec4(0.0f));
    fb.clearDepth(1.0f);
}

void GBuffer::bindPositionTarget(int layer) {
    gl::Framebuffer& fb = mTargets[static_cast<size_t>(layer)];
    fb.setDrawBufferCount(kPositionChannel + 1);
    fb.bind();
}

void GBuffer::bindTextures(int firstUnit) const {
    for (size_t i = 0; i < mChannels.size(); ++i) {
        mChannels[i].bindUnit(static_cast<GLuint>(firstUnit) + static_cast<GLuint>(i));
    }
}

const gl::Texture& GBuffer::getChannel(std::string_view name) const {
    for (size_t i = 0; i < mChannels.size(); ++i) {
        if (kChannels[i].name == name) return mChannels[i];
    }
    throw std::logic_error("no G-buffer channel named " + std::string(name));
}

size_t GBuffer::getGpuBytes() const {
    constexpr size_t kBytesRgba32F = 16;
    constexpr size_t kBytesRgba16F = 8;
    constexpr size_t kBytesRg16F = 4;
    constexpr size_t kBytesDepth = 4;
    size_t perTexel = kBytesDepth;
    for (const gl::Texture& c : mChannels) {
        perTexel += c.getFormat() == gl::Format::RGBA32F ? kBytesRgba32F
                    : c.getFormat() == gl::Format::RG16F ? kBytesRg16F
                                                         : kBytesRgba16F;
    }
    return perTexel * static_cast<size_t>(mWidth) * static_cast<size_t>(mHeight) *
           static_cast<size_t>(mLayers);
}

uint32_t getSceneGBufferChannels(const GpuScene& scene, bool wantsMotion) {
    uint32_t mask = 0;
    for (size_t i = 0; i < std::size(kChannels); ++i) {
        bool inUse = true;
        switch (kChannels[i].source) {
        case ChannelSource::Always:
            break;
        case ChannelSource::SpecularLobes:
            inUse = scene.hasSpecularLobes();
            break;
        case ChannelSource::Transmissive:
            inUse = scene.hasTransmissive();
            break;
        case ChannelSource::Emission:
            inUse = scene.hasEmission();
            break;
        case ChannelSource::Motion:
            inUse = wantsMotion;
            break;
        }
        if (inUse) mask |= 1u << i;
    }
    return mask;
}

void appendGBufferParams(std::vector<gpu::GBufferParams>& blocks, const GpuScene& scene,
                         const glm::mat4& clipFromWorld, const glm::vec4& eye,
                         const glm::mat4& previousClipFromWorld, glm::vec2 targetSizePx,
                         glm::vec2 jitterMotionPx) {
    for (uint32_t i = 0; i < scene.getInstanceCount(); ++i)
        blocks.push_back({.clipFromWorld = clipFromWorld,
                          .previousClipFromWorld = previousClipFromWorld,
                          .eye = eye,
                          .halfTargetSizePx = 0.5f * targetSizePx,
                          .jitterMotionPx = jitterMotionPx,
                          .instance = i});
}

std::vector<uint32_t> computeDrawOrder(const GpuScene& scene, const glm::vec4& eye) {
    const std::vector<Aabb>& bounds = scene.getInstanceBounds();
    std::vector<float> depth(bounds.size());
    for (size_t i = 0; i < bounds.size(); ++i) {
        const glm::vec3 centre = 0.5f * (bounds[i].lo + bounds[i].hi);
        // An orthographic eye lies along eye.xyz: depth grows against it.
        depth[i] =
            eye.w > 0.5f ? glm::length(centre - glm::vec3(eye)) : -glm::dot(centre, glm::vec3(eye));
    }
    std::vector<uint32_t> order(bounds.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&depth](uint32_t a, uint32_t b) { return depth[a] < depth[b]; });
    return order;
}

void drawSceneGBuffer(const gl::Program& program, const GpuScene& scene,
                      const ParamBlocks<gpu::GBufferParams>& blocks, size_t first,
                      std::span<const uint32_t> order) {
    assert(order.size() == scene.getInstanceCount());
    gl::applyState({.depthTest = gl::DepthTest::Less, .depthWrite = true});
    program.use();
    for (const uint32_t i : order) {
        blocks.bind(first + i);
        const auto vertexCount = static_cast<int>(scene.getInstance(i).range.y * 3u);
        gl::drawArrays(gl::Primitive::Triangles, 0, vertexCount);
    }
}

GBufferPrograms::GBufferPrograms(bool lightViews)
    : mVariants({.label = lightViews ? "light view gbuffer" : "gbuffer",
                 .stages = {{gl::ShaderStage::Vertex, "gbuffer/gbuffer.vert"},
                            {gl::ShaderStage::Fragment, "gbuffer/gbuffer.frag"}},
                 .defines = [lightViews] {
                     std::vector<std::string> defines = getGBufferDefines();
                     defines.push_back(lightViews ? "GBUFFER_LIGHT_VIEWS 1"
                                                  : "GBUFFER_LIGHT_VIEWS 0");
                     return defines;
                 }()}) {
    get(false, false); // a broken shader fails here, at start-up
}

const gl::Program& GBufferPrograms::get(bool textured, bool alphaTested) {
    return mVariants
        .get({textured ? "GBUFFER_TEXTURES 1" : "GBUFFER_TEXTURES 0",
              alphaTested ? "GBUFFER_ALPHA_TEST 1" : "GBUFFER_ALPHA_TEST 0"})
        .get();
}

const gl::Program& GBufferPrograms::get(const GpuScene& scene) {
    return get(scene.hasTextures(), scene.hasAlphaTest());
}

void GBufferPrograms::reloadIfChanged(ShaderReloadReport& report) {
    mVariants.reloadIfChanged(report);
}

} // namespace ispm
