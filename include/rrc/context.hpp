// GL 4.5 core contexts behind one small interface: EGL surfaceless (headless default), OSMesa
// (headless) and a GLFW window. Part of the rrc::context target, not of the core library: a
// renderer that owns its context does not need it.
#pragma once
#include <rrc/result.hpp>

#include <memory>
#include <string>
#include <string_view>

struct GLFWwindow;

namespace rrc {

enum class Backend { Auto, Egl, OSMesa, Glfw };

std::string_view backendName(Backend backend);
// "auto", "egl", "osmesa", "glfw" (case-insensitive); fails with BackendUnknown otherwise.
Result<Backend> parseBackend(std::string_view name);

struct ContextDesc {
    Backend backend = Backend::Auto;  // Auto: RRC_GL_BACKEND if set, else GLFW if a display
                                      // works, else EGL, else OSMesa
    int width = 1024;                 // window size (GLFW) / default framebuffer (OSMesa)
    int height = 768;
    std::string title = "rrc";
    bool visible = true;              // GLFW only
    bool debugContext = true;         // ask for a KHR_debug-friendly context
};

class Context {
public:
    // Creates the context, makes it current, loads GL and installs debug output.
    // Failures name the backend and the reason ("EGL: eglInitialize failed: EGL_NOT_INITIALIZED").
    static Result<Context> create(const ContextDesc& desc = {});

    Context(Context&&) noexcept;
    Context& operator=(Context&&) noexcept;
    ~Context();

    Backend backend() const;
    // Makes this context current and reloads the GL entry points if another provider was current.
    Result<void> makeCurrent();
    GLFWwindow* window() const;     // null for headless backends
    void swapBuffers();
    bool shouldClose() const;       // always false headless
    void pollEvents();
    std::string renderer() const;   // GL_RENDERER of this context

    struct Impl;

private:
    explicit Context(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// True when GLFW can open a window here (an X server answers).
bool displayAvailable();

} // namespace rrc
