// OpenGL 4.5 core contexts: headless (EGL device, EGL surfaceless Mesa, OSMesa) for rendering
// and tests, and a GLFW window for the viewer. Creating one loads the GL entry points (glad) and
// installs the KHR_debug logger.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace gl {

enum class ContextPath { EglDevice, EglSurfaceless, OSMesa, Window };

const char* getContextPathName(ContextPath path);

struct ContextInfo {
    ContextPath path = ContextPath::EglDevice;
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glslVersion;
    std::string device;      // EGL device extensions or other details of the path taken
    bool isSoftware = false; // llvmpipe/softpipe: timer queries are not trusted there
};

// Whether the current context renders in software (llvmpipe, softpipe): its GL_RENDERER.
bool isCurrentRendererSoftware();

class Context {
  public:
    virtual ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    // Makes the context current; GL entry points are reloaded when another context loaded them
    // last (OSMesa and EGL resolve to different libraries).
    void makeCurrent();
    const ContextInfo& getInfo() const { return mInfo; }

  protected:
    Context() = default;
    virtual void bindCurrent() = 0;
    virtual void loadFunctions() = 0;
    // Called by constructors once current: loads GL, reads the info, installs debug output.
    void initialise(ContextPath path, std::string device);
    ContextInfo mInfo;
};

// Honours ISPM_GL=egl-device|egl-surfaceless|osmesa; otherwise tries the EGL device platform
// (a hardware device first), then surfaceless Mesa, then OSMesa. Throws gl::Error listing
// why each path failed.
std::unique_ptr<Context> createHeadlessContext();

// The current context's limits that ispm's passes run into, by name (for `ispm info`), and the
// count of its extensions last.
struct ContextLimit {
    const char* name;
    int64_t value;
};
std::vector<ContextLimit> queryContextLimits();

struct WindowOptions {
    int width = 1280;
    int height = 720;
    std::string title = "ispm";
    bool visible = true;
};

class WindowContext final : public Context {
  public:
    explicit WindowContext(const WindowOptions& options);
    ~WindowContext() override;
    GLFWwindow* getWindow() const { return mWindow; }
    void setTitle(const std::string& title);
    // What the window's title bar says (GLFW 3.3 cannot read it back).
    const std::string& getTitle() const { return mTitle; }

  private:
    void bindCurrent() override;
    void loadFunctions() override;
    GLFWwindow* mWindow = nullptr;
    std::string mTitle;
};

} // namespace gl
