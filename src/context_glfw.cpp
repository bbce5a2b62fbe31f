// GLFW backend: a window with a GL 4.5 core context (needs an X server; Xvfb works).
#include "context_impl.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

namespace rrc {
namespace {

std::string lastGlfwError = "no error reported";
int liveWindows = 0;

void onGlfwError(int code, const char* description) {
    lastGlfwError = std::string(description) + " (" + std::to_string(code) + ")";
}

bool initGlfw() {
    glfwSetErrorCallback(onGlfwError);
    return glfwInit() == GLFW_TRUE;
}

struct GlfwBackend final : Context::Impl {
    GLFWwindow* handle = nullptr;
    ~GlfwBackend() override {
        if (handle) glfwDestroyWindow(handle);
        if (--liveWindows == 0) glfwTerminate();
    }
    Backend backend() const override { return Backend::Glfw; }
    bool makeCurrentRaw() override { glfwMakeContextCurrent(handle); return true; }
    GLADloadfunc loader() const override { return glfwGetProcAddress; }
    GLFWwindow* window() const override { return handle; }
    void swapBuffers() override { glfwSwapBuffers(handle); }
    bool shouldClose() const override { return glfwWindowShouldClose(handle); }
    void pollEvents() override { glfwPollEvents(); }
};

} // namespace

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!x || !*x) && (!wayland || !*wayland)) return false;
    if (!initGlfw()) return false;
    if (liveWindows == 0) glfwTerminate();
    return true;
}

Result<std::unique_ptr<Context::Impl>> createGlfwContext(const ContextDesc& desc) {
    if (!initGlfw()) return fail(LogId::ContextCreateFailed, "GLFW: glfwInit failed: " + lastGlfwError);
    ++liveWindows;
    auto ctx = std::make_unique<GlfwBackend>();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc.debugContext ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, desc.visible ? GLFW_TRUE : GLFW_FALSE);
    ctx->handle = glfwCreateWindow(desc.width, desc.height, desc.title.c_str(), nullptr, nullptr);
    if (!ctx->handle) return fail(LogId::ContextCreateFailed, "GLFW: glfwCreateWindow(GL 4.5 core) failed: " + lastGlfwError);
    return std::unique_ptr<Context::Impl>(std::move(ctx));
}

} // namespace rrc
