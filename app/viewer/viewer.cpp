// The viewer's frame loop: input (window and script) -> camera and settings -> FrameRunner ->
// debug view -> ImGui panels -> screenshots -> present.
#include "viewer/viewer.h"
#include "settings/frame_settings.h"
#include "viewer/viewer_app.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/gl.h" // before GLFW: glad's header must come first
#include "gl/state.h"
#include "gl/timer.h"
#include "render/frame.h"
#include "render/gbuffer.h"
#include "render/photon_points.h"
#include "scene/scene_loader.h"
#include "viewer/animation_panel.h"
#include "viewer/debug_view.h"
#include "viewer/fly_camera.h"
#include "viewer/imgui_layer.h"
#include "viewer/reference_view.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

namespace ispm {
namespace {

constexpr float kScriptFrameSeconds = 1.0f / 60.0f; // scripted keys move as at 60 Hz, always
constexpr float kMaxFrameSeconds = 0.1f;            // a stall must not fling the camera away
// Stats-panel read-backs (photon counts, white point) every this many frames: a few times a
// second at interactive rates, instead of a GPU wait every frame.
constexpr uint64_t kStatsReadbackFrames = 8;
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

gl::TimingMethod chooseTiming(const gl::Context& context) {
    return context.getInfo().isSoftware ? gl::TimingMethod::CpuFinish
                                        : gl::TimingMethod::TimerQuery;
}

} // namespace

Viewer::Viewer(Scene scene, const ViewerOptions& options)
    : mScene(std::move(scene)), mOptions(options), mContext(makeWindowOptions(mScene, options)),
      mWindow(mContext.getWindow()), mTiming(chooseTiming(mContext)),
      mRunner(std::make_unique<FrameRunner>(mScene, mScene.settings, mTiming)),
      mImGui(installCallbacks()), mReference(mTiming),
      mFly(mScene.camera, glm::length(mScene.computeWorldBounds().getExtent())),
      mScript(options.script) {
    if (!options.referencePath.empty()) mReference.load(options.referencePath);
    mScenePaths = listScenesBeside(mScene.sourcePath);
    mLastTime = glfwGetTime();
    glfwGetCursorPos(mWindow, &mLastCursor.x, &mLastCursor.y);
    mInput.setCursor(mLastCursor);
}

Viewer& Viewer::getViewer(GLFWwindow* window) {
    return *static_cast<Viewer*>(glfwGetWindowUserPointer(window));
}

// Events, not polled state: a click, a key tapped or a character typed between two slow frames
// (a software renderer) reaches ImGui and the camera in its order (InputQueue).
GLFWwindow* Viewer::installCallbacks() {
    glfwSetWindowUserPointer(mWindow, this);
    glfwSetCursorPosCallback(mWindow, [](GLFWwindow* w, double x, double y) {
        getViewer(w).mInput.push(InputEvent::move({x, y}));
    });
    glfwSetMouseButtonCallback(mWindow, [](GLFWwindow* w, int button, int action, int mods) {
        (void)mods;
        getViewer(w).mInput.push(InputEvent::button(button, action == GLFW_PRESS));
    });
    glfwSetScrollCallback(mWindow, [](GLFWwindow* w, double dx, double dy) {
        (void)dx;
        getViewer(w).mInput.push(InputEvent::wheel(dy));
    });
    glfwSetKeyCallback(mWindow, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        (void)scancode;
        if (action == GLFW_REPEAT) return; // held keys stay down until released
        getViewer(w).mInput.push(InputEvent::key(key, action == GLFW_PRESS, mods));
    });
    glfwSetCharCallback(mWindow, [](GLFWwindow* w, unsigned int c) {
        getViewer(w).mInput.push(InputEvent::character(c));
    });
    return mWindow;
}

// F5 and F12 act whatever has the keyboard; F1, F2 and Ctrl+Q (quit) unless a text field has it.
void Viewer::handleKeys(const FrameInput& input) {
    const bool typing = mImGui.isCapturingKeyboard();
    for (const InputEvent& e : input.events) {
        if (e.kind != InputEvent::Kind::Key || !e.down) continue;
        if (e.code == GLFW_KEY_F12) mScreenshotRequested = true;
        if (e.code == GLFW_KEY_F5) mReloadRequested = true;
        if (e.code == GLFW_KEY_F1 && !typing) mShowHelp = !mShowHelp;
        if (e.code == GLFW_KEY_F2 && !typing) mShowFrameRate = !mShowFrameRate;
        if (e.code == GLFW_KEY_Q && (e.mods & GLFW_MOD_CONTROL) != 0 && !typing) {
            glfwSetWindowShouldClose(mWindow, GLFW_TRUE);
        }
    }
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
    mShaderError = !report.errors.empty();
    mShaderStatus = strCat("shaders: rebuilt ", report.rebuilt, " of ", report.checked, " programs",
                           mShaderError ? strCat(", ", report.errors.size(), " failed (old kept):")
                                        : std::string());
    for (const std::string& error : report.errors)
        mShaderStatus += "\n" + error;
    std::fprintf(mShaderError ? stderr : stdout, "%s\n", mShaderStatus.c_str());
    std::fflush(mShaderError ? stderr : stdout);
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

// The camera's share of this frame's events: ImGui has seen them (beginFrame), so its capture
// flags are those of this frame, not the last one.
CameraInput Viewer::readUserInput(const FrameInput& in) {
    CameraInput input;
    const bool panelHasMouse = mImGui.isCapturingMouse();
    for (const InputEvent& e : in.events) {
        // A drag belongs to the camera only if it started outside the panels.
        if (e.kind == InputEvent::Kind::Button && e.code == kMouseLeft) {
            mDragging = e.down && !panelHasMouse;
        }
        if (e.kind == InputEvent::Kind::Move) {
            if (mDragging) input.dragPx += glm::vec2(e.cursor - mLastCursor);
            mLastCursor = e.cursor;
        }
        if (e.kind == InputEvent::Kind::Scroll && !panelHasMouse) {
            input.wheel += static_cast<float>(e.scroll);
        }
    }
    mCameraKeys.apply(in, mImGui.isCapturingKeyboard());
    for (const KeyAxis& k : kMoveKeys) {
        if (mCameraKeys.isHeld(k.key)) input.move += k.move;
    }
    return input;
}

// Loads another scene with the command line's settings on top and the window's size; a bad file
// is reported in the panel and the current scene stays.
void Viewer::switchScene(const std::string& path) {
    Scene next;
    try {
        next = loadScene(path);
    } catch (const InputError& e) {
        setStatus(e.what(), true);
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
    mFly = FlyCamera(mScene.camera, glm::length(mScene.computeWorldBounds().getExtent()));
    mLightEdit = LightEdit::None;
    setStatus(strCat("loaded ", path), false);
}

void Viewer::drawFrame() {
    gl::applyState({});
    gl::bindDefaultFramebuffer(mWindowWidth, mWindowHeight);
    gl::clearDefaultFramebuffer(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    const DebugView& view = mViews[static_cast<size_t>(mViewIndex)];
    if (view.source == DebugView::Source::Reference) {
        mReference.draw(*mRunner, view.referenceMode, mTransform.exposureStops,
                        mRunner->getFrameSettings().width, mRunner->getFrameSettings().height);
    } else {
        mDrawer.draw(*mRunner, view, mTransform, mRunner->getFrameSettings().width,
                     mRunner->getFrameSettings().height);
    }
    // Points are placed with the viewer camera: not over a light camera's image.
    const DebugView::Source source = mViews[static_cast<size_t>(mViewIndex)].source;
    if (source != DebugView::Source::LightGBuffer && source != DebugView::Source::LightImportance) {
        gl::bindDefaultFramebuffer(mRunner->getFrameSettings().width,
                                   mRunner->getFrameSettings().height);
        mPointsDrawer.draw(*mRunner, mPoints, mPointsColour);
    }
    gl::bindDefaultFramebuffer(mWindowWidth, mWindowHeight);
    drawPanels();
    if (mShowFrameRate) drawFrameRateOverlay();
    if (mShowHelp) drawHelp();
    if (view.referenceMode == ReferenceMode::HeatMap &&
        mReference.hasReference(mRunner->getFrameSettings().width,
                                mRunner->getFrameSettings().height)) {
        mReference.drawLegendLabels(mRunner->getFrameSettings().height);
    }
    mImGui.endFrame();
}

// One UI frame: events, panels and the picture at their own rate (FramePacer); the rendered
// frame goes on in slices between them and is shown when done. Scripts advance with rendered
// frames (a `wait 3` is three pictures) and --frames counts them, so scripted runs see the
// frames they asked for.
bool Viewer::isQuiet(double sinceDrawnMs) const {
    if (!mRunner->isFrameInProgress() || !mInput.isEmpty() || mDragging) return false;
    if (sinceDrawnMs >= kIdleRedrawMs || mScene.isAnimated() || !mPendingScenePath.empty()) {
        return false;
    }
    for (const KeyAxis& k : kMoveKeys) {
        if (mCameraKeys.isHeld(k.key)) return false; // the camera flies on every UI frame
    }
    return true;
}

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
        // Said the frame after the last command's, so that its outputs saw the panel before.
        const bool scriptInputSeen = mInput.getTakenCount() >= mScriptInputEnd;
        if (atFrameStart && !mScriptDone && !mOptions.script.empty() && mScript.isFinished() &&
            scriptInputSeen) {
            mScriptDone = true;
            setStatus(strCat("script finished (", mOptions.script.size(), " commands)"), false);
        }
        // A script's clicks and keys go through the queue as the window's do; the script goes on
        // once they have all reached a frame (the user's own events do not hold it up).
        if (atFrameStart && scriptInputSeen) {
            for (const ScriptCommand* c : mScript.advanceFrame())
                runScriptCommand(*c, scripted, afterFrame);
        }
        const FrameInput input = mInput.takeFrame();
        mImGui.beginFrame(input);
        handleKeys(input);
        if (mReloadRequested) reloadShaders();
        mReloadRequested = false;
        const Camera before = mScene.camera;
        mFly.update(scripted, kScriptFrameSeconds, mScene.camera);
        mFly.update(readUserInput(input), seconds, mScene.camera);
        if (!isSameCamera(before, mScene.camera) || mLightEdit != LightEdit::None) {
            mReference.restart();
        }
        // Edits wait for the next rendered frame (the runner keeps them until then), but lights
        // added or removed drop the frame in progress.
        if (mLightEdit == LightEdit::Values) mRunner->updateScene();
        if (mLightEdit == LightEdit::AddedOrRemoved)
            mRunner->updateScene(SceneChange::AddedOrRemoved);
        mLightEdit = LightEdit::None;
        if (mScene.isAnimated() && advanceAnimationClock(mClock, seconds)) {
            mScene.update(mClock.timeS);
            mRunner->updateScene();
            mReference.restart(); // a path-traced reference of another moment would be stale
        }

        if (!mRunner->isFrameInProgress() && !renderedQuietly) {
            const DebugView& shown = mViews[static_cast<size_t>(mViewIndex)];
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
            // Counts and the white point are read back for the Stats panel only, every few
            // frames: a read-back waits for the GPU to finish the frame.
            if (mFrameIndex++ % kStatsReadbackFrames == 0) {
                mCounts = readPhotonCounts(*mRunner);
                mLuminanceMax = mRunner->getPasses().tonemap.readLuminanceMax();
            }
            mReference.update(mScene, *mRunner);
            // The frame row counts the in-viewer path tracer too, when it ran this frame.
            std::vector<PassTiming> timings = mRunner->getTimings().passes;
            if (const std::optional<PassTiming> traced = mReference.getFrameTiming()) {
                timings.push_back(*traced);
            }
            mTimings.record(timings);
        }

        drawFrame();

        if (rendered) {
            for (const ScriptCommand* c : afterFrame)
                writeScriptOutput(*c);
            afterFrame.clear();
        }
        if (mScreenshotRequested) takeNumberedScreenshot();
        mScreenshotRequested = false;
        if (rendered) ++frame;
        if (rendered && frame == mOptions.maxFrames && !mOptions.screenshotPath.empty()) {
            takeScreenshot(mOptions.screenshotPath);
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
