// Rasterises the scene for the viewer and for each light camera (one array layer per view).
#include "render/gbuffer_pass.h"

#include "render/frame_constants.h"
#include "render/gpu_scene.h"

#include <cassert>

namespace ispm {

GBufferPass::GBufferPass()
    : mPrograms(false), mParams("gbuffer parameters"), mVertexArray("gbuffer vao") {}

void GBufferPass::resize(int width, int height) {
    if (mGBuffer.getWidth() != width || mGBuffer.getHeight() != height) {
        mGBuffer = GBuffer("viewer gbuffer", width, height, 1, false);
        mHasPrevious = false;
    }
}

void GBufferPass::execute(const FrameInputs& inputs) {
    // Velocity only for its readers: on llvmpipe its clear and writes cost the thesis preset's
    // G-buffer about 2.5 ms at 1280x1024.
    mGBuffer.setChannelsInUse(
        getSceneGBufferChannels(inputs.scene, inputs.settings.hasMotionBlur() || mKeepMotion));
    mGBuffer.clear(0);
    mGBuffer.bindTarget(0);
    mVertexArray.bind();
    inputs.scene.bind();
    // The first frame (or the first at a new size) has no last frame: it does not move.
    const glm::mat4 previous = mHasPrevious ? mPreviousClipFromWorld : inputs.clipFromWorld;
    // Accumulated frames look through sub-pixel offsets (inside both cameras): not motion.
    const glm::vec2 jitter = computeFrameJitter(inputs.settings, inputs.historyFrames);
    const glm::vec2 jitterMotion = mHasPrevious ? jitter - mPreviousJitterPx : glm::vec2(0.0f);
    mPreviousClipFromWorld = inputs.clipFromWorld;
    mPreviousJitterPx = jitter;
    mHasPrevious = true;
    std::vector<gpu::GBufferParams> blocks;
    appendGBufferParams(blocks, inputs.scene, inputs.clipFromWorld,
                        glm::vec4(inputs.cameraPosition, 1.0f), previous,
                        glm::vec2(inputs.width, inputs.height), jitterMotion);
    mParams.upload(blocks);
    drawSceneGBuffer(mPrograms.get(inputs.scene), inputs.scene, mParams, 0,
                     computeDrawOrder(inputs.scene, glm::vec4(inputs.cameraPosition, 1.0f)));
}

LightViewPass::LightViewPass()
    : mPrograms(true), mParams("light view parameters"), mVertexArray("light view vao") {}

void LightViewPass::execute(const FrameInputs& inputs) {
    executeViews(inputs, 0, getViewCount(inputs));
}

size_t LightViewPass::getViewCount(const FrameInputs& inputs) {
    return inputs.scene.getLightCameras().size();
}

void LightViewPass::executeViews(const FrameInputs& inputs, size_t firstView, size_t viewCount) {
    const std::vector<LightCamera>& cameras = inputs.scene.getLightCameras();
    assert(firstView + viewCount <= cameras.size());
    if (firstView == 0) prepare(inputs);
    mVertexArray.bind();
    inputs.scene.bind();
    for (size_t i = firstView; i < firstView + viewCount; ++i) {
        const LightCamera& cam = cameras[i];
        // A shadow-only view (the sun's fine one) serves shadow maps alone: shadow rays need none.
        if (cam.isShadowOnly && inputs.settings.shadows == gpu::kShadowsRay) continue;
        const int layer = static_cast<int>(i);
        // Only position and depth are cleared: the one reader of the other channels (photon
        // emission) reads them where position.w marks a surface, which this frame's draw wrote.
        // Clearing them too made the light views a fifth slower on llvmpipe.
        mGBuffer.clearPositions(layer);
        if (cam.isShadowOnly) {
            mGBuffer.bindPositionTarget(layer);
        } else {
            mGBuffer.bindTarget(layer);
        }
        drawSceneGBuffer(mPrograms.get(inputs.scene), inputs.scene, mParams,
                         i * inputs.scene.getInstanceCount(), mDrawOrders[i]);
    }
}

void LightViewPass::prepare(const FrameInputs& inputs) {
    const std::vector<LightCamera>& cameras = inputs.scene.getLightCameras();
    const int resolution = inputs.scene.getLightResolution();
    // At least one layer, so the light G-buffer textures exist even in a scene without lights.
    const int layers = std::max(1, static_cast<int>(cameras.size()));
    if (mGBuffer.getWidth() != resolution || mGBuffer.getLayers() != layers) {
        mGBuffer = GBuffer("light gbuffer", resolution, resolution, layers, true);
    }
    // The light views have no emission or velocity channel (viewer-only): their bits select
    // nothing here.
    mGBuffer.setChannelsInUse(getSceneGBufferChannels(inputs.scene, false));
    // Every view's blocks in one upload: view i's instances from i * instances on.
    std::vector<gpu::GBufferParams> blocks;
    mDrawOrders.clear();
    for (size_t i = 0; i < cameras.size(); ++i) {
        const LightCamera& cam = cameras[i];
        const glm::vec4 eye =
            cam.isOrthographic ? glm::vec4(-cam.axis, 0.0f) : glm::vec4(cam.origin, 1.0f);
        const glm::mat4 clipFromWorld = inputs.scene.getLightClipFromWorld(i);
        appendGBufferParams(blocks, inputs.scene, clipFromWorld, eye, clipFromWorld,
                            glm::vec2(float(resolution)));
        mDrawOrders.push_back(computeDrawOrder(inputs.scene, eye));
    }
    mParams.upload(blocks);
}

} // namespace ispm
