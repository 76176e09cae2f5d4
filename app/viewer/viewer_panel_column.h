// The viewer's panel column right of the rendered region, and its state: the scene picker, the
// debug view and its transform, photon points, reference, camera, settings, lights, animation and
// stats panels, the F1 and F2 overlays, and the widgets' places for scripts that click them.
#pragma once

#include "gl/context.h"
#include "render/frame.h"
#include "render/photon_points.h"
#include "scene/scene.h"
#include "viewer/animation_panel.h"
#include "viewer/debug_view.h"
#include "viewer/fly_camera.h"
#include "viewer/frame_pacer.h"
#include "viewer/reference_view.h"
#include "viewer/viewer_input.h"
#include "viewer/viewer_output.h"
#include "viewer/viewer_panels.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
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
// Whether the debug view's "view stops" scale applies to `view`: not to display, which is the
// tone-mapped frame (its brightness is the `exposure` setting, before the tone map).
bool usesViewStops(const DebugView& view);

// What the column shows and edits, owned by the viewer: handed in for each draw.
struct PanelContext {
    Scene& scene;
    FrameRunner& runner;
    ReferenceView& reference;
    FlyCamera& fly;
    ViewerOutput& output;
    AnimationClock& clock;
    const FramePacer& pacer;
    const gl::WindowContext& window;
    int windowWidth = 0;
    int windowHeight = 0;
    // The runner's next settings (and whatever must follow them): an edit in the settings panel.
    std::function<void(const Settings&)> applySettings;
};

// What a draw asks of the viewer, which owns what it changes.
struct PanelRequests {
    LightEdit lightEdit = LightEdit::None;
    std::string scenePath; // picked: loaded at the start of the next frame
};

class PanelColumn {
  public:
    // The scene picker lists the scenes beside `scenePath` (the first scene's, for the run).
    explicit PanelColumn(const std::string& scenePath);

    // The column, then the frame-rate overlay (F2) and the help window (F1) when shown.
    PanelRequests draw(const PanelContext& context);
    // `print_panel`: what the panel shows, for scripts and tests.
    void print(const PanelContext& context) const;

    void toggleHelp() { mShowHelp = !mShowHelp; }
    void toggleFrameRate() { mShowFrameRate = !mShowFrameRate; }
    // Shown under the View header (F5's result: its errors stay until fixed).
    void setShaderStatus(const std::string& text, bool isError);

    const DebugView& getView() const { return mViews[static_cast<size_t>(mViewIndex)]; }
    const ViewTransform& getTransform() const { return mTransform; }
    PhotonPoints getPoints() const { return mPoints; }
    PhotonColour getPointsColour() const { return mPointsColour; }
    // A script's `view`: false for a name no view has.
    bool selectView(const std::string& name);
    // A script's `points`: names that are not a choice leave that choice as it was.
    void selectPoints(const std::string& points, const std::string& colour);
    const ItemRects& getItems() const { return mItems; }

    // After each rendered frame: the photon counts and the white point (read back every few
    // frames), then the pass times with the reference's path tracer when it ran this frame.
    void readStats(const FrameRunner& runner);
    void recordTimings(const FrameRunner& runner, const ReferenceView& reference);

  private:
    void drawViewSection(const PanelContext& context);
    void drawScenePicker(const PanelContext& context, PanelRequests& requests) const;
    void drawPointColourLegend(const FrameRunner& runner) const;
    void recordItem(const std::string& name); // the last widget, for `click_item`

    std::vector<DebugView> mViews = buildDebugViews();
    int mViewIndex = 0;
    ViewTransform mTransform;
    PhotonPoints mPoints = PhotonPoints::None;
    PhotonColour mPointsColour = PhotonColour::Kind;
    bool mShowHelp = false;     // F1
    bool mShowFrameRate = true; // F2: the frame-rate overlay
    std::string mShaderStatus;  // the last reload's result
    bool mShaderError = false;
    std::vector<std::string> mScenePaths;
    std::array<char, kPathCapacity> mSavePath{"settings.json"};
    ItemRects mItems;
    TimingHistory mTimings;
    PhotonCounts mCounts;       // of a recent frame (see readStats)
    float mLuminanceMax = 0.0f; // likewise
    uint64_t mFrameIndex = 0;   // rendered frames, for the read-backs' rhythm
};

} // namespace ispm
