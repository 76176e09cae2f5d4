// DebugViewDrawer: picks the texture and the value transform of a view, then one triangle.
#include "viewer/debug_view.h"

#include "gl/gl.h"
#include "gl/state.h"
#include "render/fullscreen.h"
#include "render/gbuffer.h"
#include "render/shader_root.h"

#include <shared/scene_data.h>
#include <shared/viewer_data.h>

#include <algorithm>
#include <cmath>

namespace ispm {
namespace {

// Texture units of shaders/viewer/blit.frag.
constexpr GLuint kUnitSource = 0;
constexpr GLuint kUnitMask = 1;           // the array program's light positions
constexpr float kDisplayGamma = 2.2f;     // linear views are encoded like the default tone map
constexpr float kImportanceWhite = 20.0f; // light importance: this pdf (x uniform) shows white

ReloadableProgram buildBlitProgram(bool isArray) {
    std::vector<std::string> defines;
    if (isArray) defines.emplace_back("TEXTURE_ARRAY");
    return ReloadableProgram({.label = isArray ? "viewer blit array" : "viewer blit",
                              .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                                         {gl::ShaderStage::Fragment, "viewer/blit.frag"}},
                              .defines = defines});
}

// Scale and bias that bring a channel's typical values into [0, 1].
void getChannelTransform(std::string_view channel, float& scale, float& bias) {
    if (channel == "normal") {
        scale = 0.5f; // [-1, 1] -> [0, 1]
        bias = 0.5f;
    } else {
        scale = 1.0f;
        bias = 0.0f;
    }
}

const gl::Texture& selectTexture(const FrameRunner& runner, const DebugView& view) {
    switch (view.source) {
    case DebugView::Source::ViewerGBuffer:
        return runner.getPasses().gbuffer.getGBuffer().getChannel(view.channel);
    case DebugView::Source::LightGBuffer:
        return runner.getPasses().lightViews.getGBuffer().getChannel(view.channel);
    case DebugView::Source::LightImportance:
        return runner.getPasses().importance.getPdfMap();
    case DebugView::Source::Aov:
    case DebugView::Source::Reference: // ReferenceView draws these; `aov` is their total
        break;
    }
    return runner.getAov(view.aov);
}

} // namespace

std::vector<DebugView> buildDebugViews() {
    std::vector<DebugView> views = {{"display", DebugView::Source::Aov, Aov::Display, 0},
                                    {"direct", DebugView::Source::Aov, Aov::Direct, 0},
                                    {"indirect", DebugView::Source::Aov, Aov::Indirect, 0},
                                    {"total", DebugView::Source::Aov, Aov::Total, 0}};
    views.push_back(
        {"reference", DebugView::Source::Reference, Aov::Total, 0, ReferenceMode::Reference});
    views.push_back(
        {"side by side", DebugView::Source::Reference, Aov::Total, 0, ReferenceMode::SideBySide});
    views.push_back(
        {"error heat map", DebugView::Source::Reference, Aov::Total, 0, ReferenceMode::HeatMap});
    const auto channels = getGBufferChannels();
    for (size_t i = 0; i < channels.size(); ++i) {
        views.push_back({"gbuffer " + std::string(channels[i].name),
                         DebugView::Source::ViewerGBuffer, Aov::Display, i});
    }
    for (size_t i = 0; i < channels.size(); ++i) {
        if (channels[i].viewerOnly) continue; // light views have no such attachment
        views.push_back({"light gbuffer " + std::string(channels[i].name),
                         DebugView::Source::LightGBuffer, Aov::Display, i});
    }
    views.push_back({"light importance", DebugView::Source::LightImportance, Aov::Display, 0});
    return views;
}

int findDebugView(const std::vector<DebugView>& views, const std::string& name) {
    for (size_t i = 0; i < views.size(); ++i) {
        if (views[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

DebugViewDrawer::DebugViewDrawer()
    : mProgram2D(buildBlitProgram(false)), mProgramArray(buildBlitProgram(true)),
      mParams("viewer blit parameters", sizeof(gpu::BlitParams)), mVertexArray("viewer blit vao"),
      mSampler("viewer blit sampler", gl::Filter::Nearest, gl::Wrap::ClampToEdge) {}

void DebugViewDrawer::draw(const FrameRunner& runner, const DebugView& view,
                           const ViewTransform& transform, int width, int height) const {
    gl::applyState({});
    gl::bindDefaultFramebuffer(width, height);
    const gl::Texture& texture = selectTexture(runner, view);
    float scale = 1.0f;
    float bias = 0.0f;
    float inverseGamma = 0.0f;
    float layer = 0.0f;
    int regionWidth = width;
    int regionHeight = height;
    switch (view.source) {
    case DebugView::Source::Aov:
    case DebugView::Source::Reference:
        if (view.aov != Aov::Display) {
            scale = std::exp2(transform.exposureStops);
            inverseGamma = 1.0f / kDisplayGamma;
        }
        break;
    case DebugView::Source::ViewerGBuffer:
        getChannelTransform(getGBufferChannels()[view.channel].name, scale, bias);
        scale *= std::exp2(transform.exposureStops);
        break;
    case DebugView::Source::LightGBuffer:
    case DebugView::Source::LightImportance: {
        if (view.source == DebugView::Source::LightImportance) {
            // The pdf relative to a uniform map, gamma-encoded: 1 (the uniform share) shows dark
            // grey, kImportanceWhite times that white.
            scale = std::exp2(transform.exposureStops) / kImportanceWhite;
            inverseGamma = 1.0f / kDisplayGamma;
        } else {
            getChannelTransform(getGBufferChannels()[view.channel].name, scale, bias);
            scale *= std::exp2(transform.exposureStops);
        }
        layer = static_cast<float>(std::clamp(transform.lightLayer, 0, texture.getLayers() - 1));
        // Light cameras are square: keep their aspect in the region's lower-left square.
        regionWidth = regionHeight = std::min(width, height);
        gl::setViewport(0, 0, regionWidth, regionHeight);
        break;
    }
    }
    const ReloadableProgram& program = texture.isArray() ? mProgramArray : mProgram2D;
    program.use();
    // Light views hold their channels only where a surface is (LightViewPass).
    const bool masked = view.source == DebugView::Source::LightGBuffer;
    const gpu::BlitParams params{.regionOriginPx = glm::vec2(0.0f),
                                 .regionSizePx = glm::vec2(static_cast<float>(regionWidth),
                                                           static_cast<float>(regionHeight)),
                                 .scale = scale,
                                 .bias = bias,
                                 .inverseGamma = inverseGamma,
                                 .layer = layer,
                                 .masked = masked ? 1u : 0u};
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    texture.bindUnit(kUnitSource);
    mSampler.bindUnit(kUnitSource);
    if (texture.isArray()) {
        runner.getPasses().lightViews.getGBuffer().getChannel("position").bindUnit(kUnitMask);
        mSampler.bindUnit(kUnitMask);
    }
    mVertexArray.bind();
    drawFullscreenTriangle();
    // Passes bind their own samplers or none: leave units 0 and 1 as they expect them.
    gl::Sampler::unbindUnit(kUnitSource);
    gl::Sampler::unbindUnit(kUnitMask);
}

} // namespace ispm
