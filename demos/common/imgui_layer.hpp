// Dear ImGui on a GLFW window: context, GLFW input backend and OpenGL3 renderer (the backend
// sources of Debian's libimgui-dev, compiled with glad as their GL loader). One per window.
#pragma once
#include <rrc/result.hpp>

#include <memory>

struct GLFWwindow;

namespace rrc::demo {

class ImGuiLayer {
    struct Key { explicit Key() = default; };   // only create() can construct

public:
    explicit ImGuiLayer(Key) {}
    // Fails with ContextCreateFailed when a backend cannot initialise.
    static Result<std::unique_ptr<ImGuiLayer>> create(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    void endFrame();                  // renders into the bound framebuffer
    bool wantsMouse() const;          // the pointer is over an ImGui window
    bool wantsKeyboard() const;       // a widget has keyboard focus

private:
    bool glfwReady_ = false, openglReady_ = false;
};

} // namespace rrc::demo
