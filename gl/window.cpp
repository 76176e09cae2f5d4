// The viewer's context: a GLFW window with a 4.5 core debug context.
#include "gl/context.h"
#include "gl/gl.h"

#include <GLFW/glfw3.h>

namespace gl {

WindowContext::WindowContext(const WindowOptions& options) : mTitle(options.title) {
    if (!glfwInit()) throw Error("GLFW: cannot initialise (is there a display? try xvfb-run)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    mWindow =
        glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!mWindow) {
        glfwTerminate();
        throw Error("GLFW: cannot create a window with an OpenGL 4.5 core context");
    }
    bindCurrent();
    try {
        initialise(ContextPath::Window, "GLFW window");
    } catch (const Error&) {
        glfwDestroyWindow(mWindow);
        glfwTerminate();
        throw;
    }
}

WindowContext::~WindowContext() {
    glfwDestroyWindow(mWindow);
    glfwTerminate();
}

void WindowContext::setTitle(const std::string& title) {
    glfwSetWindowTitle(mWindow, title.c_str());
    mTitle = title;
}

void WindowContext::bindCurrent() {
    glfwMakeContextCurrent(mWindow);
}

void WindowContext::loadFunctions() {
    if (!gladLoadGL(glfwGetProcAddress))
        throw Error("GLFW: OpenGL 4.5 entry points could not be loaded");
}

} // namespace gl
