// The viewer's frame loop: input (window and script) -> camera and settings -> FrameRunner ->
// debug view -> ImGui panels -> screenshots -> present.
#include "viewer/viewer.h"

#include "core/input_error.h"
#include "core/strings.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/gl.h" // before GLFW: glad's header must come first
#include "gl/state.h"
#include "gl/timer.h"
#include "image/image_io.h"
#include "render/frame.h"
#include "render/readback.h"
#include "scene/scene_loader.h"
#include "viewer/animation_panel.h"
#include "viewer/debug_view.h"
#include "viewer/fly_camera.h"
#include "viewer/imgui_layer.h"
#include "viewer/photon_points.h"
#include "viewer/reference_view.h"
#include "viewer/screenshot.h"
#include "viewer/settings_panel.h"
#include "viewer/viewer_panels.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace ispm {
namespace {

constexpr int kPanelWidthPx = 380;                  // the panel column right of the scene region
constexpr float kScriptFrameSeconds = 1.0f / 60.0f; // scripted keys move as at 60 Hz, always
constexpr float kMaxFrameSeconds = 0.1f;            // a stall must not fling the camera away
constexpr float kMaxExposureStops = 20.0f;
constexpr size_t kPathCapacity = 512;
constexpr double kWaitFileSeconds = 60.0; // wait_file: the other side is surely stuck by then
constexpr double kWaitPollSeconds = 0.01;
// Stats-panel read-backs (photon counts, white point) every this many frames: a few times a
// second at interactive rates, instead of a GPU wait every frame.
constexpr uint64_t kStatsReadbackFrames = 8;
constexpr std::array<const char*, 4> kPointsNames = {"none", "bounce", "result", "both"};

struct KeyAxis {
    int key;
    char name;
    glm::vec3 move; // right, up, forward
};

constexpr std::array<KeyAxis, 6> kMoveKeys = {{
    {GLFW_KEY_W, 'W', {0, 0, 1}},
    {GLFW_KEY_S, 'S', {0, 0, -1}},
    {GLFW_KEY_D, 'D', {1, 0, 0}},
    {GLFW_KEY_A, 'A', {-1, 0, 0}},
    {GLFW_KEY_E, 'E', {0, 1, 0}},
    {GLFW_KEY_Q, 'Q', {0, -1, 0}},
}};

class Viewer {
  public:
    Viewer(Scene scene, const ViewerOptions& options);
    int run();

  private:
    static void onScroll(GLFWwindow* window, double dx, double dy);
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    GLFWwindow* installCallbacks();
    void syncRenderSize();
    void applySettings(const Settings& settings);
    void runScriptCommand(const ScriptCommand& c, CameraInput& input,
                          std::vector<const ScriptCommand*>& afterFrame);
    void writeScriptOutput(const ScriptCommand& c);
    CameraInput readUserInput();
    void drawPanels();
    void takeScreenshot(const std::string& path);
    void drawScenePicker();
    void switchScene(const std::string& path);
    void reloadShaders();
    void waitForFile(const ScriptCommand& c);

    Scene mScene;
    ViewerOptions mOptions;
    gl::WindowContext mContext;
    GLFWwindow* mWindow;
    gl::TimingMethod mTiming;
    std::unique_ptr<FrameRunner> mRunner; // rebuilt when the scene picker loads another scene
    ImGuiLayer mImGui;
    DebugViewDrawer mDrawer;
    PhotonPointsDrawer mPointsDrawer;
    PhotonPoints mPoints = PhotonPoints::None;
    ReferenceView mReference;
    bool mReloadRequested = false; // F5
    std::string mShaderStatus;     // the last reload's result (its errors stay until fixed)
    bool mShaderError = false;
    std::vector<DebugView> mViews = buildDebugViews();
    int mViewIndex = 0;
    ViewTransform mTransform;
    FlyCamera mFly;
    std::vector<std::string> mScenePaths;
    std::string mPendingScenePath;
    ScriptPlayer mScript;
    TimingHistory mTimings;
    PhotonCounts mCounts;       // of a recent frame (see kStatsReadbackFrames)
    float mLuminanceMax = 0.0f; // likewise
    uint64_t mFrameIndex = 0;
    int mWindowWidth = 0;
    int mWindowHeight = 0;
    double mLastTime = 0.0;
    double mPendingWheel = 0.0;
    glm::dvec2 mLastCursor{0.0};
    bool mDragging = false;
    bool mScreenshotRequested = false; // F12
    int mScreenshotCount = 0;
    LightEdit mLightEdit = LightEdit::None;
    AnimationClock mClock;
    std::array<char, kPathCapacity> mSavePath{"settings.json"};
    std::string mStatus;
};

gl::WindowOptions makeWindowOptions(const Scene& scene, const ViewerOptions& options) {
    gl::WindowOptions w;
    w.width = scene.settings.getInt("width") + kPanelWidthPx;
    w.height = scene.settings.getInt("height");
    w.title = strCat("ispm view ", scene.sourcePath);
    w.visible = options.visible;
    return w;
}

gl::TimingMethod chooseTiming(const gl::Context& context) {
    return context.getInfo().isSoftware ? gl::TimingMethod::CpuFinish
                                        : gl::TimingMethod::TimerQuery;
}

Viewer::Viewer(Scene scene, const ViewerOptions& options)
    : mScene(std::move(scene)), mOptions(options), mContext(makeWindowOptions(mScene, options)),
      mWindow(mContext.getWindow()), mTiming(chooseTiming(mContext)),
      mRunner(std::make_unique<FrameRunner>(mScene, mScene.settings, mTiming)),
      mImGui(installCallbacks()),
      mFly(mScene.camera, glm::length(mScene.computeWorldBounds().getExtent())),
      mScript(options.script) {
    if (!options.referencePath.empty()) mReference.load(options.referencePath);
    const std::filesystem::path folder =
        std::filesystem::path(mScene.sourcePath).parent_path().empty()
            ? std::filesystem::path(".")
            : std::filesystem::path(mScene.sourcePath).parent_path();
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (entry.path().extension() == ".json") mScenePaths.push_back(entry.path().string());
    }
    std::sort(mScenePaths.begin(), mScenePaths.end());
    mLastTime = glfwGetTime();
    glfwGetCursorPos(mWindow, &mLastCursor.x, &mLastCursor.y);
}

// The callbacks go in before ImGui's backend, which chains them. Events, not polled state: a
// key tapped between two slow frames (a software renderer) must still count.
GLFWwindow* Viewer::installCallbacks() {
    glfwSetWindowUserPointer(mWindow, this);
    glfwSetScrollCallback(mWindow, onScroll);
    glfwSetKeyCallback(mWindow, onKey);
    // Held keys are polled; sticky keys keep a short press visible until the next poll.
    glfwSetInputMode(mWindow, GLFW_STICKY_KEYS, GLFW_TRUE);
    return mWindow;
}

void Viewer::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    (void)scancode;
    (void)mods;
    if (key == GLFW_KEY_F12 && action == GLFW_PRESS) {
        static_cast<Viewer*>(glfwGetWindowUserPointer(window))->mScreenshotRequested = true;
    }
    if (key == GLFW_KEY_F5 && action == GLFW_PRESS) {
        static_cast<Viewer*>(glfwGetWindowUserPointer(window))->mReloadRequested = true;
    }
}

void Viewer::onScroll(GLFWwindow* window, double dx, double dy) {
    (void)dx;
    static_cast<Viewer*>(glfwGetWindowUserPointer(window))->mPendingWheel += dy;
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
    if (mRunner->getWidth() == width && mRunner->getHeight() == height) return;
    Settings next = mRunner->getSettings();
    next.set("width", width, "viewer window");
    next.set("height", height, "viewer window");
    applySettings(next);
}

void Viewer::runScriptCommand(const ScriptCommand& c, CameraInput& input,
                              std::vector<const ScriptCommand*>& afterFrame) {
    using Kind = ScriptCommand::Kind;
    switch (c.kind) {
    case Kind::Key:
        for (const KeyAxis& k : kMoveKeys) {
            if (k.name == c.text[0]) input.move += k.move;
        }
        break;
    case Kind::MouseDrag:
        input.dragPx += glm::vec2(c.x, c.y);
        break;
    case Kind::Wheel:
        input.wheel += c.x;
        break;
    case Kind::Set: {
        const std::string name = c.text.substr(0, c.text.find('='));
        if (isWindowSetting(name)) {
            throw InputError(
                strCat(c.where, ": '", name, "' follows the window; use --width/--height"));
        }
        Settings next = mRunner->getSettings();
        next.setFromString(c.text, c.where);
        applySettings(next);
        break;
    }
    case Kind::View: {
        const int index = findDebugView(mViews, c.text);
        if (index < 0) throw InputError(strCat(c.where, ": unknown view '", c.text, "'"));
        mViewIndex = index;
        break;
    }
    case Kind::Points:
        for (size_t i = 0; i < kPointsNames.size(); ++i) {
            if (c.text == kPointsNames[i]) mPoints = static_cast<PhotonPoints>(i);
        }
        break;
    case Kind::ResetCamera:
        mFly.reset(mScene.camera);
        break;
    case Kind::ReloadShaders:
        reloadShaders();
        break;
    case Kind::WaitFile:
        waitForFile(c);
        break;
    case Kind::LoadReference:
        mReference.load(c.path);
        break;
    case Kind::RenderReference:
        mReference.setRendering(c.text == "on");
        break;
    case Kind::ComputeMetrics:
    case Kind::WriteAov:
    case Kind::Screenshot:
    case Kind::SaveSettings:
        afterFrame.push_back(&c);
        break;
    case Kind::Frames:
        break;
    }
}

// Blocks the frame loop (the window stays responsive) until another process created the file.
void Viewer::waitForFile(const ScriptCommand& c) {
    const double start = glfwGetTime();
    while (!std::filesystem::exists(c.path)) {
        if (glfwGetTime() - start > kWaitFileSeconds) {
            throw InputError(strCat(c.where, ": gave up waiting for ", c.path));
        }
        glfwWaitEventsTimeout(kWaitPollSeconds);
    }
}

void Viewer::writeScriptOutput(const ScriptCommand& c) {
    if (c.kind == ScriptCommand::Kind::Screenshot) {
        takeScreenshot(c.path);
        return;
    }
    if (c.kind == ScriptCommand::Kind::ComputeMetrics) {
        std::printf("reference: %s\n", mReference.computeMetrics(*mRunner).c_str());
        std::fflush(stdout);
        return;
    }
    if (c.kind == ScriptCommand::Kind::SaveSettings) {
        saveRenderBlock(c.path, mRunner->getSettings());
        return;
    }
    const Aov aov = c.text == "display" ? Aov::Display : parseAov(c.text, c.where);
    writeImage(c.path, readTextureImage(mRunner->getAov(aov)));
    std::printf("wrote %s (%s)\n", c.path.c_str(), c.text.c_str());
    std::fflush(stdout);
}

CameraInput Viewer::readUserInput() {
    CameraInput input;
    glm::dvec2 cursor;
    glfwGetCursorPos(mWindow, &cursor.x, &cursor.y);
    const bool leftDown = glfwGetMouseButton(mWindow, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    // A drag belongs to the camera only if it started outside the panels.
    if (leftDown && !mDragging && !mImGui.isCapturingMouse()) mDragging = true;
    if (!leftDown) mDragging = false;
    if (mDragging) input.dragPx = glm::vec2(cursor - mLastCursor);
    mLastCursor = cursor;
    if (!mImGui.isCapturingMouse()) input.wheel = static_cast<float>(mPendingWheel);
    mPendingWheel = 0.0;
    if (!mImGui.isCapturingKeyboard()) {
        for (const KeyAxis& k : kMoveKeys) {
            if (glfwGetKey(mWindow, k.key) == GLFW_PRESS) input.move += k.move;
        }
    }
    return input;
}

void Viewer::takeScreenshot(const std::string& path) {
    writeScreenshot(path, mWindowWidth, mWindowHeight);
    mStatus = strCat("wrote ", path);
    std::printf("wrote %s (%dx%d window)\n", path.c_str(), mWindowWidth, mWindowHeight);
    std::fflush(stdout); // the viewer runs long: say so now, not at exit
}

void Viewer::drawPanels() {
    const int renderWidth = mRunner->getWidth();
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(renderWidth), 0.0f));
    ImGui::SetNextWindowSize(
        ImVec2(static_cast<float>(kPanelWidthPx), static_cast<float>(mWindowHeight)));
    ImGui::Begin("ispm", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    drawScenePicker();
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        const DebugView& current = mViews[static_cast<size_t>(mViewIndex)];
        if (ImGui::BeginCombo("debug view", current.name.c_str())) {
            for (size_t i = 0; i < mViews.size(); ++i) {
                if (ImGui::Selectable(mViews[i].name.c_str(), static_cast<int>(i) == mViewIndex)) {
                    mViewIndex = static_cast<int>(i);
                }
            }
            ImGui::EndCombo();
        }
        ImGui::SliderFloat("view stops", &mTransform.exposureStops, -kMaxExposureStops,
                           kMaxExposureStops);
        int points = static_cast<int>(mPoints);
        if (ImGui::Combo("photon points", &points, kPointsNames.data(),
                         static_cast<int>(kPointsNames.size()))) {
            mPoints = static_cast<PhotonPoints>(points);
        }
        if (current.source == DebugView::Source::LightGBuffer ||
            current.source == DebugView::Source::LightImportance) {
            const int layers = mRunner->getLightGBuffer().getLayers();
            ImGui::SliderInt("light camera", &mTransform.lightLayer, 0, std::max(0, layers - 1));
        }
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("F12: screenshot   F5: reload shaders   drag: look   WASD/QE: fly   "
                           "wheel: speed");
        ImGui::PopStyleColor();
        if (!mShaderStatus.empty()) {
            const ImVec4 kErrorColour(1.0f, 0.4f, 0.4f, 1.0f);
            const ImVec4 kOkColour(0.6f, 0.9f, 0.6f, 1.0f);
            ImGui::PushStyleColor(ImGuiCol_Text, mShaderError ? kErrorColour : kOkColour);
            ImGui::TextWrapped("%s", mShaderStatus.c_str());
            ImGui::PopStyleColor();
        }
    }
    if (ImGui::CollapsingHeader("Reference")) mReference.drawPanel(*mRunner);
    if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        float speed = mFly.getSpeed();
        if (ImGui::DragFloat("speed m/s", &speed, speed * 0.01f, 1e-4f, 1e6f, "%.3g")) {
            mFly.setSpeed(speed);
        }
        const glm::vec3& p = mScene.camera.position;
        ImGui::Text("position %.3f %.3f %.3f", static_cast<double>(p.x), static_cast<double>(p.y),
                    static_cast<double>(p.z));
        if (ImGui::Button("reset camera")) mFly.reset(mScene.camera);
    }
    if (ImGui::CollapsingHeader("Settings", ImGuiTreeNodeFlags_DefaultOpen)) {
        Settings edited = mRunner->getSettings();
        if (drawSettingsPanel(edited)) applySettings(edited);
        ImGui::InputText("##savepath", mSavePath.data(), mSavePath.size());
        ImGui::SameLine();
        if (ImGui::Button("save")) {
            saveRenderBlock(mSavePath.data(), mRunner->getSettings());
            mStatus = strCat("saved the render block to ", mSavePath.data());
        }
    }
    if (ImGui::CollapsingHeader("Lights")) {
        const LightEdit edit =
            drawLightsPanel(mScene.lights, mScene.camera.position,
                            glm::length(mScene.computeWorldBounds().getExtent()));
        if (edit != LightEdit::None && mLightEdit != LightEdit::AddedOrRemoved) mLightEdit = edit;
    }
    if (mScene.isAnimated() && ImGui::CollapsingHeader("Animation")) drawAnimationPanel(mClock);
    if (ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawStatsPanel(mTimings, mCounts, mContext.getInfo().renderer,
                       gl::getTimingMethodName(mRunner->getTimingMethod()), mLuminanceMax,
                       mRunner->getAccumulatedFrames());
    }
    if (!mStatus.empty()) ImGui::TextWrapped("%s", mStatus.c_str());
    ImGui::End();
}

void Viewer::drawScenePicker() {
    if (mScenePaths.empty()) return;
    const std::string current = std::filesystem::path(mScene.sourcePath).filename().string();
    if (!ImGui::BeginCombo("scene", current.c_str())) return;
    std::string picked;
    for (const std::string& path : mScenePaths) {
        const std::string name = std::filesystem::path(path).filename().string();
        if (ImGui::Selectable(name.c_str(), name == current)) picked = path;
    }
    ImGui::EndCombo();
    // Switched at the start of the next frame: this frame's panels still read the old runner.
    if (!picked.empty()) mPendingScenePath = picked;
}

// Loads another scene with the command line's settings on top and the window's size; a bad file
// is reported in the panel and the current scene stays.
void Viewer::switchScene(const std::string& path) {
    Scene next;
    try {
        next = loadScene(path);
    } catch (const InputError& e) {
        mStatus = e.what();
        return;
    }
    next.settings.merge(mOptions.commandLine);
    next.settings.set("width", mRunner->getWidth(), "viewer window");
    next.settings.set("height", mRunner->getHeight(), "viewer window");
    mReference.restart(); // its path tracer holds a reference to mScene too
    mRunner.reset();      // holds a reference to mScene
    mScene = std::move(next);
    mRunner = std::make_unique<FrameRunner>(mScene, mScene.settings, mTiming);
    mFly = FlyCamera(mScene.camera, glm::length(mScene.computeWorldBounds().getExtent()));
    mLightEdit = LightEdit::None;
    mStatus = strCat("loaded ", path);
}

int Viewer::run() {
    int frame = 0;
    while (!glfwWindowShouldClose(mWindow)) {
        if (mOptions.maxFrames >= 0 && frame >= mOptions.maxFrames) break;
        glfwPollEvents();
        if (!mPendingScenePath.empty()) {
            switchScene(mPendingScenePath);
            mPendingScenePath.clear();
        }
        syncRenderSize();
        const double now = glfwGetTime();
        const float seconds = std::min(static_cast<float>(now - mLastTime), kMaxFrameSeconds);
        mLastTime = now;

        CameraInput scripted;
        std::vector<const ScriptCommand*> afterFrame;
        for (const ScriptCommand* c : mScript.advanceFrame())
            runScriptCommand(*c, scripted, afterFrame);
        if (mReloadRequested) reloadShaders();
        mReloadRequested = false;
        const Camera before = mScene.camera;
        mFly.update(scripted, kScriptFrameSeconds, mScene.camera);
        mFly.update(readUserInput(), seconds, mScene.camera);
        if (!isSameCamera(before, mScene.camera) || mLightEdit != LightEdit::None) {
            mReference.restart();
        }
        if (mLightEdit == LightEdit::Values) mRunner->updateScene();
        if (mLightEdit == LightEdit::AddedOrRemoved) mRunner->rebuildScene();
        mLightEdit = LightEdit::None;
        if (mScene.isAnimated() && advanceAnimationClock(mClock, seconds)) {
            mScene.update(mClock.timeS);
            mRunner->updateScene();
            mReference.restart(); // a path-traced reference of another moment would be stale
        }

        mRunner->renderFrame();
        mTimings.record(mRunner->getLastTimings());
        // Counts and the white point are read back for the Stats panel only, every few frames:
        // a read-back waits for the GPU to finish the frame.
        if (mFrameIndex++ % kStatsReadbackFrames == 0) {
            mCounts = mRunner->readPhotonCounts();
            mLuminanceMax = mRunner->readLuminanceMax();
        }
        mReference.update(mScene, *mRunner);

        gl::applyState({});
        gl::bindDefaultFramebuffer(mWindowWidth, mWindowHeight);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const DebugView& view = mViews[static_cast<size_t>(mViewIndex)];
        if (view.source == DebugView::Source::Reference) {
            mReference.draw(*mRunner, view.referenceMode, mTransform.exposureStops,
                            mRunner->getWidth(), mRunner->getHeight());
        } else {
            mDrawer.draw(*mRunner, view, mTransform, mRunner->getWidth(), mRunner->getHeight());
        }
        // Points are placed with the viewer camera: not over a light camera's image.
        const DebugView::Source source = mViews[static_cast<size_t>(mViewIndex)].source;
        if (source != DebugView::Source::LightGBuffer &&
            source != DebugView::Source::LightImportance) {
            mPointsDrawer.draw(*mRunner, mPoints, mRunner->getWidth(), mRunner->getHeight());
        }
        gl::bindDefaultFramebuffer(mWindowWidth, mWindowHeight);
        mImGui.beginFrame();
        drawPanels();
        if (view.referenceMode == ReferenceMode::HeatMap && mReference.hasReference()) {
            mReference.drawLegendLabels(mRunner->getHeight());
        }
        mImGui.endFrame();

        for (const ScriptCommand* c : afterFrame)
            writeScriptOutput(*c);
        if (mScreenshotRequested) {
            takeScreenshot(strCat("ispm_screenshot_", mScreenshotCount++, ".png"));
            mScreenshotRequested = false;
        }
        ++frame;
        if (frame == mOptions.maxFrames && !mOptions.screenshotPath.empty()) {
            takeScreenshot(mOptions.screenshotPath);
        }
        glfwSwapBuffers(mWindow);
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

} // namespace

int runViewer(Scene scene, const ViewerOptions& options) {
    Viewer viewer(std::move(scene), options);
    return viewer.run();
}

} // namespace ispm
