// The viewer's state and parts (`ispm view`), shared by its sources: viewer.cpp runs the frame
// loop, viewer_script.cpp plays scripted input and writes the script's outputs,
// viewer_panel_column.cpp draws the ImGui panel column. Internal to app/viewer/.
#pragma once

#include "gl/context.h"
#include "gl/gl.h" // before GLFW: glad's header must come first
#include "gl/timer.h"
#include "render/frame.h"
#include "render/photon_points.h"
#include "scene/scene.h"
#include "viewer/animation_panel.h"
#include "viewer/debug_view.h"
#include "viewer/fly_camera.h"
#include "viewer/frame_pacer.h"
#include "viewer/imgui_layer.h"
#include "viewer/input_queue.h"
#include "viewer/input_script.h"
#include "viewer/reference_view.h"
#include "viewer/settings_panel.h"
#include "viewer/viewer.h"
#include "viewer/viewer_panels.h"

#include <GLFW/glfw3.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ispm {

inline constexpr int kPanelWidthPx = 380;    // the panel column right of the scene region
inline constexpr size_t kPathCapacity = 512; // the panel's save-path field

// The scene files (.json) in the folder of `scenePath`, sorted: the scene picker's list.
std::vector<std::string> listScenesBeside(const std::string& scenePath);
// What "auto" gives a derived setting now (the runner's resolved settings and scene, the white
// point read back); nullopt where the mode does not use it.
std::optional<double> findDerivedValue(const FrameRunner& runner, float luminanceMax,
                                       std::string_view name);

struct KeyAxis {
    int key;
    char name;
    glm::vec3 move; // right, up, forward
};

inline constexpr std::array<KeyAxis, 6> kMoveKeys = {{
    {GLFW_KEY_W, 'W', {0, 0, 1}},
    {GLFW_KEY_S, 'S', {0, 0, -1}},
    {GLFW_KEY_D, 'D', {1, 0, 0}},
    {GLFW_KEY_A, 'A', {-1, 0, 0}},
    {GLFW_KEY_E, 'E', {0, 1, 0}},
    {GLFW_KEY_Q, 'Q', {0, -1, 0}},
}};

// Whether the debug view's "view stops" scale applies to `view`: not to display, which is the
// tone-mapped frame (its brightness is the `exposure` setting, before the tone map).
bool usesViewStops(const DebugView& view);

// A widget's place on the panel as last drawn, for scripts that click it (`click_item`).
struct ItemRect {
    glm::vec2 min{0.0f};
    glm::vec2 max{0.0f};
};

class Viewer {
  public:
    Viewer(Scene scene, const ViewerOptions& options);
    int run();

  private:
    static Viewer& getViewer(GLFWwindow* window);
    GLFWwindow* installCallbacks();
    void handleKeys(const FrameInput& input); // F1, F5, F12, Ctrl+Q
    void pushScriptInput(const ScriptCommand& c);
    void recordItem(const std::string& name); // the last widget, for `click_item`
    void printPanel();                        // `print_panel`
    void drawHelp();                          // the F1 window: keys and mouse
    void drawFrameRateOverlay();
    float computeStatusFooterHeight() const;
    void syncRenderSize();
    void applySettings(const Settings& settings);
    void runScriptCommand(const ScriptCommand& c, CameraInput& input,
                          std::vector<const ScriptCommand*>& afterFrame);
    void writeScriptOutput(const ScriptCommand& c);
    CameraInput readUserInput(const FrameInput& input);
    void drawPanels();
    void takeScreenshot(const std::string& path); // throws when the file cannot be written
    void takeNumberedScreenshot();                // F12
    void saveSettings(const std::string& path);   // the panel's "save"
    void setStatus(const std::string& text, bool isError);
    void drawScenePicker();
    void drawPointColourLegend() const; // what the photon points' colours mean
    void switchScene(const std::string& path);
    void reloadShaders();
    void waitForFile(const ScriptCommand& c);
    void drawFrame(); // the frame or debug view, the photon points, the panels
    // Whether this UI frame may go to the frame's slice alone: a frame is being drawn and no
    // event, held key, drag or animation asks for the window, drawn `sinceDrawnMs` ago.
    bool isQuiet(double sinceDrawnMs) const;

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
    PhotonColour mPointsColour = PhotonColour::Kind;
    ReferenceView mReference;      // after mTiming
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
    FramePacer mPacer;    // UI frames at their own rate, rendered frames in slices between them
    PhotonCounts mCounts; // of a recent frame (see kStatsReadbackFrames)
    float mLuminanceMax = 0.0f; // likewise
    uint64_t mFrameIndex = 0;
    int mWindowWidth = 0;
    int mWindowHeight = 0;
    double mLastTime = 0.0;
    InputQueue mInput; // the window's events (and a script's stand-ins), in order
    CameraKeys mCameraKeys;
    uint64_t mScriptInputEnd = 0; // the queue's count after the script's last event
    glm::dvec2 mLastCursor{0.0};
    bool mDragging = false;
    bool mShowHelp = false;            // F1
    bool mShowFrameRate = true;        // F2: the frame-rate overlay
    bool mScreenshotRequested = false; // F12
    bool mScriptDone = false;          // said so in the panel once
    std::map<std::string, ItemRect> mItems;
    int mScreenshotCount = 0;
    LightEdit mLightEdit = LightEdit::None;
    AnimationClock mClock;
    std::array<char, kPathCapacity> mSavePath{"settings.json"};
    std::string mStatus; // the panel's message line (a file written, a path refused ...)
    bool mStatusIsError = false;
};

} // namespace ispm
