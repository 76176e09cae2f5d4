// Context creation paths. EGL entry points come from glad's EGL loader (dlopen of libEGL), GL ones
// from glad's GL loader fed by the context's own GetProcAddress.
#include "gl/context.h"

#include "gl/debug.h"
#include "gl/gl.h"

#include <glad/egl.h>
// osmesa.h includes GL/gl.h, which glad's header has already stood in for.
#include <GL/osmesa.h>

#include <cstdlib>
#include <string_view>
#include <vector>

namespace gl {
namespace {

constexpr int kGlMajor = 4;
constexpr int kGlMinor = 5;
constexpr int kMaxEglDevices = 16;

GLADapiproc loadEglProc(const char* name) {
    return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

GLADapiproc loadOsMesaProc(const char* name) {
    return reinterpret_cast<GLADapiproc>(OSMesaGetProcAddress(name));
}

void loadGlFunctions(GLADloadfunc load, const char* path) {
    const int version = gladLoadGL(load);
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < kGlMajor * 10 + kGlMinor) {
        throw Error(std::string(path) + ": OpenGL 4.5 entry points could not be loaded");
    }
}

bool hasExtension(const char* list, std::string_view name) {
    if (!list) return false;
    std::string_view all(list);
    size_t pos = 0;
    while ((pos = all.find(name, pos)) != std::string_view::npos) {
        const size_t end = pos + name.size();
        const bool startsWord = pos == 0 || all[pos - 1] == ' ';
        const bool endsWord = end == all.size() || all[end] == ' ';
        if (startsWord && endsWord) return true;
        pos = end;
    }
    return false;
}

class EglContext final : public Context {
  public:
    EglContext(ContextPath path, EGLDisplay display, std::string device) : mDisplay(display) {
        if (!gladLoaderLoadEGL(mDisplay)) throw Error("EGL: cannot load EGL 1.5 for the display");
        EGLint major = 0;
        EGLint minor = 0;
        if (!eglInitialize(mDisplay, &major, &minor)) throw Error("EGL: eglInitialize failed");
        // Reload now that the display is initialised: display extensions become visible.
        gladLoaderLoadEGL(mDisplay);
        if (!hasExtension(eglQueryString(mDisplay, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
            throw Error("EGL: display lacks EGL_KHR_no_config_context");
        }
        if (!eglBindAPI(EGL_OPENGL_API)) throw Error("EGL: eglBindAPI(OpenGL) failed");
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     kGlMajor,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     kGlMinor,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG,
                                     EGL_TRUE,
                                     EGL_NONE};
        mContext = eglCreateContext(mDisplay, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        if (mContext == EGL_NO_CONTEXT) {
            throw Error("EGL: cannot create an OpenGL 4.5 core context");
        }
        bindCurrent();
        initialise(path, std::move(device));
    }

    ~EglContext() override {
        eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        // No eglTerminate: EGL hands out one display per device, so terminating it would
        // destroy every other context on it too.
        eglDestroyContext(mDisplay, mContext);
    }

  private:
    void bindCurrent() override {
        if (!eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext)) {
            throw Error("EGL: eglMakeCurrent failed");
        }
    }
    void loadFunctions() override { loadGlFunctions(loadEglProc, "egl"); }

    EGLDisplay mDisplay = EGL_NO_DISPLAY;
    EGLContext mContext = EGL_NO_CONTEXT;
};

class OsMesaContext final : public Context {
  public:
    OsMesaContext() {
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  0,
                                  OSMESA_PROFILE,
                                  OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  kGlMajor,
                                  OSMESA_CONTEXT_MINOR_VERSION,
                                  kGlMinor,
                                  0};
        mContext = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!mContext) throw Error("OSMesa: cannot create an OpenGL 4.5 core context");
        bindCurrent();
        initialise(ContextPath::OSMesa, "OSMesa");
    }

    ~OsMesaContext() override { OSMesaDestroyContext(mContext); }

  private:
    void loadFunctions() override { loadGlFunctions(loadOsMesaProc, "osmesa"); }
    void bindCurrent() override {
        // OSMesa needs a colour buffer to be current; ispm never draws to it (FBOs only).
        if (!OSMesaMakeCurrent(mContext, mPixel.data(), GL_UNSIGNED_BYTE, 1, 1)) {
            throw Error("OSMesa: OSMesaMakeCurrent failed");
        }
    }

    OSMesaContext mContext = nullptr;
    std::vector<unsigned char> mPixel = std::vector<unsigned char>(4);
};

bool isSoftwareDevice(const char* extensions) {
    return hasExtension(extensions, "EGL_MESA_device_software");
}

std::unique_ptr<Context> createEglDeviceContext() {
    if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) throw Error("egl-device: libEGL not found");
    if (!eglQueryDevicesEXT || !eglGetPlatformDisplayEXT || !eglQueryDeviceStringEXT) {
        throw Error("egl-device: EGL_EXT_device_enumeration/platform_device not available");
    }
    EGLDeviceEXT devices[kMaxEglDevices];
    EGLint count = 0;
    if (!eglQueryDevicesEXT(kMaxEglDevices, devices, &count) || count == 0) {
        throw Error("egl-device: no EGL devices");
    }
    // Hardware devices first, then software ones.
    std::vector<EGLDeviceEXT> ordered;
    for (int pass = 0; pass < 2; ++pass) {
        for (EGLint i = 0; i < count; ++i) {
            const bool software =
                isSoftwareDevice(eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS));
            if (software == (pass == 1)) ordered.push_back(devices[i]);
        }
    }
    std::string failures;
    for (EGLDeviceEXT device : ordered) {
        const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (display == EGL_NO_DISPLAY) continue;
        try {
            return std::make_unique<EglContext>(ContextPath::EglDevice, display,
                                                extensions ? extensions : "");
        } catch (const Error& e) {
            failures += std::string(failures.empty() ? "" : "; ") + e.what();
        }
    }
    throw Error("egl-device: no device gave a 4.5 core context (" + failures + ")");
}

std::unique_ptr<Context> createEglSurfacelessContext() {
    if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) throw Error("egl-surfaceless: libEGL not found");
    if (!eglGetPlatformDisplayEXT) throw Error("egl-surfaceless: EGL_EXT_platform_base missing");
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) throw Error("egl-surfaceless: no surfaceless Mesa display");
    return std::make_unique<EglContext>(ContextPath::EglSurfaceless, display, "surfaceless");
}

} // namespace

const char* getContextPathName(ContextPath path) {
    switch (path) {
    case ContextPath::EglDevice:
        return "egl-device";
    case ContextPath::EglSurfaceless:
        return "egl-surfaceless";
    case ContextPath::OSMesa:
        return "osmesa";
    case ContextPath::Window:
        return "glfw-window";
    }
    return "?";
}

bool isCurrentRendererSoftware() {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string_view renderer(text ? text : "");
    return renderer.find("llvmpipe") != std::string_view::npos ||
           renderer.find("softpipe") != std::string_view::npos;
}

namespace {
const Context* gLoadedBy = nullptr; // whose GetProcAddress filled glad's pointers
} // namespace

Context::~Context() {
    if (gLoadedBy == this) gLoadedBy = nullptr;
}

void Context::makeCurrent() {
    bindCurrent();
    if (gLoadedBy != this) {
        loadFunctions();
        gLoadedBy = this;
    }
}

void Context::initialise(ContextPath path, std::string device) {
    loadFunctions();
    gLoadedBy = this;
    auto read = [](GLenum name) {
        const auto* text = reinterpret_cast<const char*>(glGetString(name));
        return std::string(text ? text : "");
    };
    mInfo.path = path;
    mInfo.vendor = read(GL_VENDOR);
    mInfo.renderer = read(GL_RENDERER);
    mInfo.version = read(GL_VERSION);
    mInfo.glslVersion = read(GL_SHADING_LANGUAGE_VERSION);
    mInfo.device = std::move(device);
    mInfo.isSoftware = isCurrentRendererSoftware() || isSoftwareDevice(mInfo.device.c_str());
    installDebugOutput();
}

std::unique_ptr<Context> createHeadlessContext() {
    using Factory = std::unique_ptr<Context> (*)();
    struct Candidate {
        const char* name;
        Factory create;
    };
    const Candidate candidates[] = {
        {"egl-device", createEglDeviceContext},
        {"egl-surfaceless", createEglSurfacelessContext},
        {"osmesa", [] { return std::unique_ptr<Context>(std::make_unique<OsMesaContext>()); }},
    };
    const char* forced = std::getenv("ISPM_GL");
    if (forced && *forced) {
        for (const Candidate& c : candidates) {
            if (std::string_view(forced) == c.name) return c.create();
        }
        throw Error(std::string("ISPM_GL=") + forced +
                    ": expected egl-device, egl-surfaceless or osmesa");
    }
    std::string failures;
    for (const Candidate& c : candidates) {
        try {
            return c.create();
        } catch (const Error& e) {
            failures += std::string(failures.empty() ? "" : "; ") + e.what();
        }
    }
    throw Error("no OpenGL 4.5 core context: " + failures);
}

std::vector<ContextLimit> queryContextLimits() {
    struct Query {
        const char* name;
        GLenum pname;
    };
    const Query queries[] = {
        {"max texture size", GL_MAX_TEXTURE_SIZE},
        {"max array texture layers", GL_MAX_ARRAY_TEXTURE_LAYERS},
        {"max colour attachments", GL_MAX_COLOR_ATTACHMENTS},
        {"max SSBO bindings", GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS},
        {"max SSBO size (bytes)", GL_MAX_SHADER_STORAGE_BLOCK_SIZE},
        {"max compute invocations", GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS},
        {"max compute shared bytes", GL_MAX_COMPUTE_SHARED_MEMORY_SIZE},
        {"max TF buffers", GL_MAX_TRANSFORM_FEEDBACK_BUFFERS},
        {"max TF interleaved comps", GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS},
        {"max geometry out vertices", GL_MAX_GEOMETRY_OUTPUT_VERTICES},
        {"extensions", GL_NUM_EXTENSIONS},
    };
    std::vector<ContextLimit> limits;
    for (const Query& q : queries) {
        GLint64 value = 0;
        glGetInteger64v(q.pname, &value);
        limits.push_back({q.name, static_cast<int64_t>(value)});
    }
    return limits;
}

} // namespace gl
