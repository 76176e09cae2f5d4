// The viewer's debug views: the frame's outputs (display, direct, indirect, total) and every
// channel of the viewer and light G-buffers (from the G-buffer table), drawn into the window's
// scene region by one small full-screen program.
#pragma once

#include "gl/objects.h"
#include "gl/program.h"
#include "render/frame.h"

#include <string>
#include <vector>

namespace ispm {

struct DebugView {
    enum class Source { Aov, ViewerGBuffer, LightGBuffer };
    std::string name; // as in the menu and in scripts: "display", "gbuffer normal", ...
    Source source = Source::Aov;
    Aov aov = Aov::Display;
    size_t channel = 0; // G-buffer channel index
};

// Display first (the default), then the linear AOVs, then the G-buffer channels.
std::vector<DebugView> buildDebugViews();
// Index of `name` in `views`, or -1.
int findDebugView(const std::vector<DebugView>& views, const std::string& name);

// How a view's values become display values.
struct ViewTransform {
    float exposureStops = 0.0f; // all but display: values x 2^stops (AOVs then gamma-encoded)
    int lightLayer = 0;         // light G-buffer: which light camera
};

class DebugViewDrawer {
  public:
    DebugViewDrawer();
    // Draws `view` of `runner`'s last frame into the default framebuffer's region
    // [0, width) x [0, height); applies its own state first, so nothing ImGui left matters.
    void draw(const FrameRunner& runner, const DebugView& view, const ViewTransform& transform,
              int width, int height) const;

  private:
    gl::Program mProgram2D;
    gl::Program mProgramArray;
    gl::VertexArray mVertexArray;
    gl::Sampler mSampler;
};

} // namespace ispm
