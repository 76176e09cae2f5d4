// Dear ImGui on the viewer's GLFW window (the GLFW and OpenGL3 backends of Debian's libimgui).
// RAII: the constructor installs the backends, the destructor removes them.
#pragma once

struct GLFWwindow;

namespace ispm {

class ImGuiLayer {
  public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    // Renders the UI into the bound default framebuffer (the backend restores the GL state it
    // changes; the passes set their own state anyway).
    void endFrame();
    // True while ImGui uses the mouse or keyboard: the fly camera must not react then.
    bool isCapturingMouse() const;
    bool isCapturingKeyboard() const;
};

} // namespace ispm
