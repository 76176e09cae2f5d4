// ImGuiLayer: context, backends and the GLSL version they compile for.
#include "viewer/imgui_layer.h"

#include "gl/gl.h"

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
    // The backend chains any callbacks installed before it (the viewer's scroll callback).
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true) || !ImGui_ImplOpenGL3_Init(kGlslVersion)) {
        ImGui::DestroyContext();
        throw std::runtime_error("ImGui: cannot initialise the GLFW/OpenGL3 backends");
    }
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
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
