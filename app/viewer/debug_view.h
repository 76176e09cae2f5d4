// The viewer's debug views: the frame's outputs (display, direct, indirect, total) and every
// channel of the viewer and light G-buffers (from the G-buffer table), drawn into the window's
// scene region by one small full-screen program.
#pragma once

#include "gl/objects.h"
#include "render/frame.h"
#include "render/reloadable_program.h"

#include <string>
#include <vector>

namespace ispm {

// The views that need a reference image (ReferenceView draws them).
enum class ReferenceMode { Reference, SideBySide, HeatMap };

struct DebugView {
    enum class Source { Aov, ViewerGBuffer, LightGBuffer, LightImportance, Reference };
    std::string name; // as in the menu and in scripts: "display", "gbuffer normal", ...
    Source source = Source::Aov;
    Aov aov = Aov::Display;
    size_t channel = 0; // G-buffer channel index
    ReferenceMode referenceMode = ReferenceMode::Reference;
};

// Display first (the default), then the linear AOVs, the reference views and the G-buffer
// channels.
std::vector<DebugView> buildDebugViews();
// Index of `name` in `views`, or -1.
int findDebugView(const std::vector<DebugView>& views, const std::string& name);

// How a view's values become display values.
struct ViewTransform {
    float exposureStops = 0.0f; // all but display: values x 2^stops (AOVs then gamma-encoded)
    int lightLayer = 0;         // light G-buffer and importance: which light camera
};

class DebugViewDrawer {
  public:
    DebugViewDrawer();
    // Draws `view` of `runner`'s last frame into the default framebuffer's region
    // [0, width) x [0, height); applies its own state first, so nothing ImGui left matters.
    void draw(const FrameRunner& runner, const DebugView& view, const ViewTransform& transform,
              int width, int height) const;
    void reloadPrograms(ShaderReloadReport& report) {
        mProgram2D.reloadIfChanged(report);
        mProgramArray.reloadIfChanged(report);
    }

  private:
    ReloadableProgram mProgram2D;
    ReloadableProgram mProgramArray;
    gl::Buffer mParams; // gpu::BlitParams
    gl::VertexArray mVertexArray;
    gl::Sampler mSampler;
};

} // namespace ispm
