// Dear ImGui on the viewer's GLFW window (the GLFW and OpenGL3 backends of Debian's libimgui).
// RAII: the constructor installs the backends, the destructor removes them.
#pragma once

#include "viewer/input_queue.h"

struct GLFWwindow;

namespace ispm {

class ImGuiLayer {
  public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // Starts an ImGui frame with this frame's share of the window's events (InputQueue).
    void beginFrame(const FrameInput& input);
    // Renders the UI into the bound default framebuffer (the backend restores the GL state it
    // changes; the passes set their own state anyway).
    void endFrame();
    // True while ImGui uses the mouse or keyboard (as of beginFrame): the fly camera must not
    // react then.
    bool isCapturingMouse() const;
    bool isCapturingKeyboard() const;
};

} // namespace ispm
