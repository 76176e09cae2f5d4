// The viewer (`ispm view`) composed of its parts, shared by its sources: viewer.cpp runs the frame
// loop, viewer_script.cpp hands a script's commands to the parts they steer. The parts: input
// (viewer_input.h), the panel column (viewer_panel_column.h), files and messages (viewer_output.h).
// Internal to app/viewer/.
#pragma once

#include "gl/context.h"
#include "gl/gl.h" // before GLFW: glad's header must come first
#include "gl/timer.h"
#include "render/frame.h"
#include "render/photon_points.h"
#include "scene/scene.h"
#include "viewer/animation_panel.h"
#include "viewer/debug_view.h"
#include "viewer/frame_pacer.h"
#include "viewer/imgui_layer.h"
#include "viewer/input_script.h"
#include "viewer/reference_view.h"
#include "viewer/viewer.h"
#include "viewer/viewer_input.h"
#include "viewer/viewer_output.h"
#include "viewer/viewer_panel_column.h"
#include "viewer/viewer_panels.h"

#include <GLFW/glfw3.h>

#include <memory>
#include <string>
#include <vector>

namespace ispm {

// Composes the parts and keeps the frame loop's own state: the scene, the window, the runner and
// what draws its images, the clocks, and what a key or a panel asked of the next frame.
class Viewer {
  public:
    Viewer(Scene scene, const ViewerOptions& options);
    int run();

  private:
    void applySettings(const Settings& settings);
    void applyKeys(const ViewerKeys& keys);
    void syncRenderSize();
    void switchScene(const std::string& path);
    void updateCameraAndScene(const CameraInput& scripted, const FrameInput& input, float seconds);
    void reloadShaders();
    void advanceScript(CameraInput& input, std::vector<const ScriptCommand*>& afterFrame);
    void runScriptCommand(const ScriptCommand& c, CameraInput& input,
                          std::vector<const ScriptCommand*>& afterFrame);
    void writeScriptOutput(const ScriptCommand& c);
    PanelContext makePanelContext();
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
    ViewerInput mInput;                   // the window's callbacks: before ImGui starts
    ImGuiLayer mImGui;
    DebugViewDrawer mDrawer;
    PhotonPointsDrawer mPointsDrawer;
    ReferenceView mReference; // after mTiming
    PanelColumn mPanels;
    ViewerOutput mOutput;
    FramePacer mPacer; // UI frames at their own rate, rendered frames in slices between them
    std::string mPendingScenePath;
    LightEdit mLightEdit = LightEdit::None;
    AnimationClock mClock;
    int mWindowWidth = 0;
    int mWindowHeight = 0;
    double mLastTime = 0.0;
    bool mReloadRequested = false;     // F5
    bool mScreenshotRequested = false; // F12
};

} // namespace ispm
