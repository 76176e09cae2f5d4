// ImGuiLayer: context, backends and the GLSL version they compile for; the viewer's input events
// fed to ImGui in their order (the GLFW backend's own callbacks would poll the mouse once a frame).
#include "viewer/imgui_layer.h"

#include "gl/gl.h" // before GLFW: glad's header must come first

#include <GLFW/glfw3.h>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <stdexcept>

namespace ispm {
namespace {

constexpr const char* kGlslVersion = "#version 450"; // the context is 4.5 core

} // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    // No imgui.ini: the layout is fixed by the viewer, and runs must not write into the cwd.
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    // No backend callbacks: the viewer queues the window's events and feeds them in beginFrame.
    if (!ImGui_ImplGlfw_InitForOpenGL(window, false) || !ImGui_ImplOpenGL3_Init(kGlslVersion)) {
        ImGui::DestroyContext();
        throw std::runtime_error("ImGui: cannot initialise the GLFW/OpenGL3 backends");
    }
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame(const FrameInput& input) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame(); // display size, time step, cursor shape; its polled mouse is
                               // replaced
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(static_cast<float>(input.cursor.x), static_cast<float>(input.cursor.y));
    for (int i = 0; i < kMouseButtonCount; ++i)
        io.MouseDown[i] = input.buttons[static_cast<size_t>(i)];
    for (const InputEvent& e : input.events) {
        switch (e.kind) {
        case InputEvent::Kind::Key:
            if (e.code >= 0 && e.code < IM_ARRAYSIZE(io.KeysDown)) io.KeysDown[e.code] = e.down;
            break;
        case InputEvent::Kind::Char:
            io.AddInputCharacter(static_cast<unsigned int>(e.code));
            break;
        case InputEvent::Kind::Scroll:
            io.MouseWheel += static_cast<float>(e.scroll);
            break;
        case InputEvent::Kind::Move:
        case InputEvent::Kind::Button:
            break;
        }
    }
    io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
    io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
    io.KeyAlt = io.KeysDown[GLFW_KEY_LEFT_ALT] || io.KeysDown[GLFW_KEY_RIGHT_ALT];
    io.KeySuper = io.KeysDown[GLFW_KEY_LEFT_SUPER] || io.KeysDown[GLFW_KEY_RIGHT_SUPER];
    ImGui::NewFrame();
}

void ImGuiLayer::endFrame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::isCapturingMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}
bool ImGuiLayer::isCapturingKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}

} // namespace ispm
