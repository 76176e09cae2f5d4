// The viewer's frame loop: input (window and script) -> camera and settings -> FrameRunner ->
// debug view -> ImGui panels -> screenshots -> present.
#include "viewer/viewer.h"
#include "viewer/viewer_app.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/debug.h"
#include "gl/state.h"
#include "render/gbuffer.h"
#include "scene/scene_loader.h"
#include "settings/frame_settings.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace ispm {
namespace {

constexpr float kScriptFrameSeconds = 1.0f / 60.0f; // scripted keys move as at 60 Hz, always
constexpr float kMaxFrameSeconds = 0.1f;            // a stall must not fling the camera away
// A window with nothing happening is redrawn this often while a frame is drawn in slices (ImGui's
// hover tooltips and text caret move on time, not on events).
constexpr double kIdleRedrawMs = 100.0;

std::string makeWindowTitle(const Scene& scene) {
    return strCat("ispm view ", scene.sourcePath);
}

gl::WindowOptions makeWindowOptions(const Scene& scene, const ViewerOptions& options) {
    gl::WindowOptions w;
    const FrameSettings settings = resolveFrameSettings(scene.settings);
    w.width = settings.width + kPanelWidthPx;
    w.height = settings.height;
    w.title = makeWindowTitle(scene);
    w.visible = options.visible;
    return w;
}

} // namespace

Viewer::Viewer(Scene scene, const ViewerOptions& options)
    : mScene(std::move(scene)), mOptions(options), mContext(makeWindowOptions(mScene, options)),
      mWindow(mContext.getWindow()), mTiming(gl::chooseTimingMethod(mContext.getInfo())),
      mRunner(std::make_unique<FrameRunner>(mScene, mScene.settings, mTiming)),
      mInput(mWindow, mScene, options.script), mImGui(mWindow), mReference(mTiming),
      mPanels(mScene.sourcePath) {
    if (!options.referencePath.empty()) mReference.load(options.referencePath);
    mLastTime = glfwGetTime();
}

void Viewer::applyKeys(const ViewerKeys& keys) {
    if (keys.screenshot) mScreenshotRequested = true;
    if (keys.reloadShaders) mReloadRequested = true;
    if (keys.toggleHelp) mPanels.toggleHelp();
    if (keys.toggleFrameRate) mPanels.toggleFrameRate();
    if (keys.quit) glfwSetWindowShouldClose(mWindow, GLFW_TRUE);
}

void Viewer::applySettings(const Settings& settings) {
    mRunner->setSettings(settings);
    mReference.restart(); // the path tracer reads the settings once, when it is built
}

// F5: the frame's passes and the viewer's own programs rebuild what changed on disk; a program
// that fails keeps running its old version, and the log shows in the panel and on stderr.
void Viewer::reloadShaders() {
    ShaderReloadReport report = mRunner->reloadShaders();
    mDrawer.reloadPrograms(report);
    mPointsDrawer.reloadPrograms(report);
    mReference.reloadPrograms(report);
    const bool failed = !report.errors.empty();
    std::string status =
        strCat("shaders: rebuilt ", report.rebuilt, " of ", report.checked, " programs",
               failed ? strCat(", ", report.errors.size(), " failed (old kept):") : std::string());
    for (const std::string& error : report.errors)
        status += "\n" + error;
    mPanels.setShaderStatus(status, failed);
    std::fprintf(failed ? stderr : stdout, "%s\n", status.c_str());
    std::fflush(failed ? stderr : stdout);
}

// The render region is the window minus the panel column: keep width/height in step with it.
void Viewer::syncRenderSize() {
    glfwGetFramebufferSize(mWindow, &mWindowWidth, &mWindowHeight);
    const int width = std::max(1, mWindowWidth - kPanelWidthPx);
    const int height = std::max(1, mWindowHeight);
    // The next frame's size: a resize asked for while a frame is drawn waits for it to end.
    Settings next = mRunner->getSettings();
    if (next.getInt("width") == width && next.getInt("height") == height) return;
    next.set("width", width, "viewer window");
    next.set("height", height, "viewer window");
    applySettings(next);
}

// Loads another scene with the command line's settings on top and the window's size; a bad file
// is reported in the panel and the current scene stays.
void Viewer::switchScene(const std::string& path) {
    Scene next;
    try {
        next = loadScene(path);
    } catch (const InputError& e) {
        mOutput.setStatus(e.what(), true);
        return;
    }
    next.settings.merge(mOptions.commandLine);
    next.settings.set("width", mRunner->getFrameSettings().width, "viewer window");
    next.settings.set("height", mRunner->getFrameSettings().height, "viewer window");
    mReference.restart(); // its path tracer holds a reference to mScene too
    mRunner.reset();      // holds a reference to mScene
    mScene = std::move(next);
    mContext.setTitle(makeWindowTitle(mScene));
    mRunner = std::make_unique<FrameRunner>(mScene, mScene.settings, mTiming);
    mInput.resetFly(mScene);
    mLightEdit = LightEdit::None;
    mOutput.setStatus(strCat("loaded ", path), false);
}

PanelContext Viewer::makePanelContext() {
    return {mScene,
            *mRunner,
            mReference,
            mInput.getFly(),
            mOutput,
            mClock,
            mPacer,
            mContext,
            mWindowWidth,
            mWindowHeight,
            [this](const Settings& settings) { applySettings(settings); }};
}

void Viewer::drawFrame() {
    gl::applyState({});
    gl::bindDefaultFramebuffer(mWindowWidth, mWindowHeight);
    gl::clearDefaultFramebuffer(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    const DebugView& view = mPanels.getView();
    const int width = mRunner->getFrameSettings().width; // the rendered region's
    const int height = mRunner->getFrameSettings().height;
    if (view.source == DebugView::Source::Reference) {
        mReference.draw(*mRunner, view.referenceMode, mPanels.getTransform().exposureStops, width,
                        height);
    } else {
        mDrawer.draw(*mRunner, view, mPanels.getTransform(), width, height);
    }
    // Points are placed with the viewer camera: not over a light camera's image.
    if (view.source != DebugView::Source::LightGBuffer &&
        view.source != DebugView::Source::LightImportance) {
        gl::bindDefaultFramebuffer(width, height);
        mPointsDrawer.draw(*mRunner, mPanels.getPoints(), mPanels.getPointsColour());
    }
    gl::bindDefaultFramebuffer(mWindowWidth, mWindowHeight);
    const PanelRequests requests = mPanels.draw(makePanelContext());
    mLightEdit = requests.lightEdit; // the last frame's was applied before this draw
    if (!requests.scenePath.empty()) mPendingScenePath = requests.scenePath;
    if (view.referenceMode == ReferenceMode::HeatMap && mReference.hasReference(width, height)) {
        mReference.drawLegendLabels(height);
    }
    mImGui.endFrame();
}

bool Viewer::isQuiet(double sinceDrawnMs) const {
    if (!mRunner->isFrameInProgress() || !mInput.isIdle()) return false;
    return sinceDrawnMs < kIdleRedrawMs && !mScene.isAnimated() && mPendingScenePath.empty();
}

// The camera flies (the script's input at a fixed step, the user's by the wall clock) and edits
// of the lights and the animation reach the runner; the reference restarts on any of them.
void Viewer::updateCameraAndScene(const CameraInput& scripted, const FrameInput& input,
                                  float seconds) {
    const Camera before = mScene.camera;
    mInput.getFly().update(scripted, kScriptFrameSeconds, mScene.camera);
    const CameraInput user =
        mInput.readCamera(input, mImGui.isCapturingMouse(), mImGui.isCapturingKeyboard());
    mInput.getFly().update(user, seconds, mScene.camera);
    if (!isSameCamera(before, mScene.camera) || mLightEdit != LightEdit::None) {
        mReference.restart();
    }
    // Edits wait for the next rendered frame (the runner keeps them until then), but lights
    // added or removed drop the frame in progress.
    if (mLightEdit == LightEdit::Values) mRunner->updateScene();
    if (mLightEdit == LightEdit::AddedOrRemoved) mRunner->updateScene(SceneChange::AddedOrRemoved);
    mLightEdit = LightEdit::None;
    if (mScene.isAnimated() && advanceAnimationClock(mClock, seconds)) {
        mScene.update(mClock.timeS);
        mRunner->updateScene();
        mReference.restart(); // a path-traced reference of another moment would be stale
    }
}

// One UI frame: events, panels and the picture at their own rate (FramePacer); the rendered
// frame goes on in slices between them and is shown when done. Scripts advance with rendered
// frames (a `wait 3` is three pictures) and --frames counts them, so scripted runs see the
// frames they asked for.
int Viewer::run() {
    using Clock = std::chrono::steady_clock;
    const auto msBetween = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    int frame = 0;
    Clock::time_point uiFrameEnd = Clock::now(); // the last UI frame's end, quiet ones included
    Clock::time_point drawnEnd = uiFrameEnd;     // the last redraw's
    Clock::time_point renderFrameStart = uiFrameEnd;
    std::vector<const ScriptCommand*> afterFrame; // outputs of the rendered frame in progress
    double sinceFrameBeganS = 0.0;                // wall time since the last frame began
    while (!glfwWindowShouldClose(mWindow)) {
        if (mOptions.maxFrames >= 0 && frame >= mOptions.maxFrames) break;
        glfwPollEvents();
        if (!mPendingScenePath.empty()) {
            switchScene(mPendingScenePath);
            mPendingScenePath.clear();
        }
        syncRenderSize();
        // While a frame is drawn and nothing happens, the window is not redrawn (at most every
        // kIdleRedrawMs): the frame gets the time. Any event ends the quiet at once.
        bool renderedQuietly = false;
        if (isQuiet(msBetween(drawnEnd, Clock::now()))) {
            renderedQuietly = mRunner->continueFrame(mPacer.getRenderBudgetMs());
            const Clock::time_point end = Clock::now();
            mPacer.recordQuietSlice(msBetween(uiFrameEnd, end));
            uiFrameEnd = end;
            if (!renderedQuietly) continue;
            mPacer.recordRenderFrame(msBetween(renderFrameStart, Clock::now()));
        }
        const double now = glfwGetTime();
        const float seconds = std::min(static_cast<float>(now - mLastTime), kMaxFrameSeconds);
        mLastTime = now;
        sinceFrameBeganS += static_cast<double>(seconds);

        CameraInput scripted;
        // A frame done in a quiet slice is shown (and its script outputs written) before the
        // script goes on.
        const bool atFrameStart = !mRunner->isFrameInProgress() && !renderedQuietly;
        if (atFrameStart) advanceScript(scripted, afterFrame);
        const FrameInput input = mInput.takeFrame();
        mImGui.beginFrame(input);
        applyKeys(ViewerInput::readKeys(input, mImGui.isCapturingKeyboard()));
        if (mReloadRequested) reloadShaders();
        mReloadRequested = false;
        updateCameraAndScene(scripted, input, seconds);

        if (!mRunner->isFrameInProgress() && !renderedQuietly) {
            const DebugView& shown = mPanels.getView();
            mRunner->setPresentation(
                {.timeStepS = sinceFrameBeganS, // eye adaptation follows the wall clock
                 .keepVelocity = shown.source == DebugView::Source::ViewerGBuffer &&
                                 getGBufferChannels()[shown.channel].name == "velocity"});
            sinceFrameBeganS = 0.0;
            renderFrameStart = Clock::now();
            mRunner->beginFrame(mPacer.getRenderBudgetMs());
        }
        const Clock::time_point sliceStart = Clock::now();
        const bool rendered = renderedQuietly || mRunner->continueFrame(mPacer.getRenderBudgetMs());
        const double sliceMs = msBetween(sliceStart, Clock::now());
        if (rendered && !renderedQuietly) {
            mPacer.recordRenderFrame(msBetween(renderFrameStart, Clock::now()));
        }
        if (rendered) {
            mPanels.readStats(*mRunner);
            mReference.update(mScene, *mRunner);
            mPanels.recordTimings(*mRunner, mReference);
        }

        drawFrame();

        if (rendered) {
            for (const ScriptCommand* c : afterFrame)
                writeScriptOutput(*c);
            afterFrame.clear();
        }
        if (mScreenshotRequested) mOutput.takeNumberedScreenshot(mWindowWidth, mWindowHeight);
        mScreenshotRequested = false;
        if (rendered) ++frame;
        if (rendered && frame == mOptions.maxFrames && !mOptions.screenshotPath.empty()) {
            mOutput.takeScreenshot(mOptions.screenshotPath, mWindowWidth, mWindowHeight);
        }
        glfwSwapBuffers(mWindow);
        const Clock::time_point end = Clock::now();
        mPacer.recordUiFrame(msBetween(uiFrameEnd, end), sliceMs);
        uiFrameEnd = drawnEnd = end;
    }
    const gl::DebugCounts debug = gl::getDebugCounts();
    if (debug.errors > 0) {
        std::fprintf(stderr, "ispm: %llu OpenGL errors were reported while viewing\n",
                     static_cast<unsigned long long>(debug.errors));
        for (const std::string& message : gl::getRecentDebugErrors()) {
            std::fprintf(stderr, "  %s\n", message.c_str());
        }
        return 1;
    }
    return 0;
}

int runViewer(Scene scene, const ViewerOptions& options) {
    Viewer viewer(std::move(scene), options);
    return viewer.run();
}

} // namespace ispm
