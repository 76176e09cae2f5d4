// ReferenceView: the reference texture (loaded, or the path tracer's running sum), its three
// views in one full-screen program, and the metrics read back on request.
#include "viewer/reference_view.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/gl.h"
#include "gl/state.h"
#include "image/image_io.h"
#include "image/metrics.h"
#include "render/fullscreen.h"
#include "render/readback.h"

#include <shared/scene_data.h>
#include <shared/viewer_data.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ispm {
namespace {

// Texture units of shaders/viewer/reference_view.frag.
constexpr GLuint kUnitTotal = 0;
constexpr GLuint kUnitReference = 1;
constexpr float kDisplayGamma = 2.2f;    // as the other linear views (debug_view.cpp)
constexpr float kLegendHeightPx = 12.0f; // the legend bar of reference_view.frag
// The path tracer restarts only after the camera has been still this long: flying would
// otherwise rebuild its GPU scene every frame for a single sample.
constexpr int kStillFramesBeforeRestart = 2;
constexpr int kMaxSamplesPerFrame = 64;
// "Follow" refreshes the metrics this often: a read-back of two images and an SSIM per frame
// would halve the frame rate.
constexpr int kAutoMetricsFrames = 30;
constexpr float kMinHeatMax = 0.01f;
constexpr float kMaxHeatMax = 10.0f;
constexpr const char* kTracerTimingName = "reference (path tracer)"; // its Stats row
const ImVec4 kWarningColour(1.0f, 0.4f, 0.4f, 1.0f);

uint32_t toGpuMode(ReferenceMode mode) {
    switch (mode) {
    case ReferenceMode::Reference:
        return gpu::kReferenceModeReference;
    case ReferenceMode::SideBySide:
        return gpu::kReferenceModeSideBySide;
    case ReferenceMode::HeatMap:
        return gpu::kReferenceModeHeatMap;
    }
    return gpu::kReferenceModeReference;
}

} // namespace

ReferenceView::ReferenceView(gl::TimingMethod timing)
    : mProgram({.label = "viewer reference",
                .stages = {{gl::ShaderStage::Vertex, "lib/fullscreen.vert"},
                           {gl::ShaderStage::Fragment, "viewer/reference_view.frag"}}}),
      mParams("viewer reference parameters", sizeof(gpu::ReferenceViewParams)),
      mVertexArray("viewer reference vao"),
      mSampler("viewer reference sampler", gl::Filter::Nearest, gl::Wrap::ClampToEdge),
      mTimer(timing) {}

void ReferenceView::load(const std::string& path) {
    Image image = readImage(path); // throws InputError naming the file
    // Texture rows start at the bottom, Image rows at the top; alpha 1 reads as one sample.
    std::vector<glm::vec4> texels(image.getPixelCount());
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            texels[static_cast<size_t>((image.height - 1 - y) * image.width + x)] =
                glm::vec4(image.at(x, y), 1.0f);
        }
    }
    mLoaded = gl::Texture::create2D("viewer loaded reference", gl::Format::RGBA32F, image.width,
                                    image.height);
    mLoaded.uploadRgba(texels);
    mLoadedImage = std::move(image);
    mLoadedPath = path;
    mStatus = strCat("loaded ", path, " (", mLoadedImage.width, "x", mLoadedImage.height, ")");
}

void ReferenceView::setRendering(bool rendering) {
    mRendering = rendering;
    if (!rendering) mPass.reset();
}

void ReferenceView::restart() {
    mPass.reset();
    mStillFrames = 0;
    mMetricsText.clear();
}

void ReferenceView::update(const Scene& scene, const FrameRunner& runner) {
    mFrameTiming.reset();
    if (mRendering && (mPass || ++mStillFrames >= kStillFramesBeforeRestart)) {
        if (!mPass) {
            try {
                mPass = std::make_unique<ReferencePass>(scene, runner.getPasses().scene,
                                                        runner.getSettings());
            } catch (const gl::Error& e) {
                // Its shader is read anew at every restart: an edit in progress must not end
                // the session.
                mStatus = e.what();
                mRendering = false;
                return;
            }
        }
        mTimer.begin(kTracerTimingName);
        for (int i = 0; i < mSamplesPerFrame; ++i)
            mPass->addSample();
        mTimer.end();
        if (const auto samples = mTimer.collect()) {
            for (const gl::PassTimer::Sample& sample : *samples)
                mLastTracedMs = sample.ms;
        }
        mFrameTiming = PassTiming{kTracerTimingName, mLastTracedMs};
    }
    if (mAutoMetrics &&
        hasReference(runner.getFrameSettings().width, runner.getFrameSettings().height) &&
        ++mFramesSinceMetrics >= kAutoMetricsFrames) {
        computeMetrics(runner);
    }
}

const gl::Texture* ReferenceView::getSource(int width, int height) const {
    if (mRendering) return mPass ? &mPass->getAccumulation() : nullptr;
    if (mLoadedImage.isEmpty() || !describeSizeMismatch(width, height).empty()) return nullptr;
    return &mLoaded;
}

std::string ReferenceView::describeMissing(int width, int height) const {
    if (mRendering) return mPass ? "" : "no reference yet: the path tracer waits for the camera";
    if (mLoadedImage.isEmpty()) return "no reference: load one or render it";
    return describeSizeMismatch(width, height);
}

std::string ReferenceView::describeSizeMismatch(int width, int height) const {
    if (mLoadedImage.width == width && mLoadedImage.height == height) return {};
    return strCat("the reference is ", mLoadedImage.width, "x", mLoadedImage.height,
                  ", the render ", width, "x", height,
                  ": not shown or compared (resize the "
                  "window or load one of the render's size)");
}

std::string ReferenceView::computeMetrics(const FrameRunner& runner) {
    mFramesSinceMetrics = 0;
    const std::string missing =
        describeMissing(runner.getFrameSettings().width, runner.getFrameSettings().height);
    if (!missing.empty()) {
        mMetricsText = missing;
    } else {
        const Image total = readTextureImage(runner.getAov(Aov::Total));
        const Image reference = mRendering ? mPass->readMean() : mLoadedImage;
        try {
            const ImageMetrics m = ispm::computeMetrics(total, reference);
            mMetricsText = strCat("relMSE ", m.relMse, "  SSIM ", m.ssim);
            if (mRendering) mMetricsText += strCat("  (", mPass->getSampleCount(), " spp)");
        } catch (const InputError& e) {
            mMetricsText = e.what(); // another size: names both
        }
    }
    return mMetricsText;
}

void ReferenceView::draw(const FrameRunner& runner, ReferenceMode mode, float exposureStops,
                         int width, int height) const {
    const gl::Texture* source = getSource(width, height);
    if (source == nullptr) return; // the panel says why the region is black
    gl::applyState({});
    gl::bindDefaultFramebuffer(width, height);
    mProgram.use();
    const gpu::ReferenceViewParams params{
        .regionOriginPx = glm::vec2(0.0f),
        .regionSizePx = glm::vec2(static_cast<float>(width), static_cast<float>(height)),
        .scale = std::exp2(exposureStops),
        .inverseGamma = 1.0f / kDisplayGamma,
        .heatMapMax = mHeatMax,
        .mode = toGpuMode(mode)};
    mParams.upload(0, sizeof(params), &params);
    mParams.bindBase(gl::BufferTarget::Uniform, gpu::kBindingPassParams);
    runner.getAov(Aov::Total).bindUnit(kUnitTotal);
    source->bindUnit(kUnitReference);
    mSampler.bindUnit(kUnitTotal);
    mSampler.bindUnit(kUnitReference);
    mVertexArray.bind();
    drawFullscreenTriangle();
    // Passes bind their own samplers or none: leave the units as they expect them.
    gl::Sampler::unbindUnit(kUnitTotal);
    gl::Sampler::unbindUnit(kUnitReference);
}

void ReferenceView::drawLegendLabels(int height) const {
    ImDrawList* list = ImGui::GetForegroundDrawList();
    const float y = static_cast<float>(height) - kLegendHeightPx - ImGui::GetTextLineHeight();
    const std::string label = strCat("0 .. ", mHeatMax, " relative error");
    list->AddText(ImVec2(2.0f, y), IM_COL32_WHITE, label.c_str());
}

void ReferenceView::drawPanel(const FrameRunner& runner) {
    ImGui::InputText("##reference", mPathInput.data(), mPathInput.size());
    ImGui::SameLine();
    if (ImGui::Button("load")) {
        try {
            load(mPathInput.data());
            setRendering(false);
        } catch (const InputError& e) {
            mStatus = e.what();
        }
    }
    bool rendering = mRendering;
    if (ImGui::Checkbox("render (path tracer)", &rendering)) setRendering(rendering);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::SliderInt("spp/frame", &mSamplesPerFrame, 1, kMaxSamplesPerFrame);
    if (mRendering) {
        ImGui::Text("%d samples per pixel%s", mPass ? mPass->getSampleCount() : 0,
                    mPass ? "" : " (waiting for the camera to stop)");
    } else if (!mLoadedPath.empty()) {
        ImGui::TextWrapped("file: %s", mLoadedPath.c_str());
        const std::string mismatch =
            describeSizeMismatch(runner.getFrameSettings().width, runner.getFrameSettings().height);
        if (!mismatch.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, kWarningColour);
            ImGui::TextWrapped("%s", mismatch.c_str());
            ImGui::PopStyleColor();
        }
    } else {
        ImGui::TextDisabled("no reference: load a .pfm/.exr or render one");
    }
    ImGui::SliderFloat("heat map max", &mHeatMax, kMinHeatMax, kMaxHeatMax, "%.3g",
                       ImGuiSliderFlags_Logarithmic);
    if (ImGui::Button("compute relMSE / SSIM")) computeMetrics(runner);
    ImGui::SameLine();
    ImGui::Checkbox("follow", &mAutoMetrics);
    if (!mMetricsText.empty()) ImGui::TextWrapped("%s", mMetricsText.c_str());
    if (!mStatus.empty()) ImGui::TextWrapped("%s", mStatus.c_str());
}

} // namespace ispm
