// The window loop (GLFW backend): the demo's colour texture (or, with V, its hit/miss view)
// drawn to the window, a fly camera (WASD/QE, left-drag to look, wheel for speed), M toggles the
// mode, C returns to the scripted camera path, Space pauses the clock, Esc quits; an ImGui
// overlay shows fps, frame time, the demo's stats and its own controls. With --frames and --out,
// the last frame as shown (overlay included) is also written as <name>_window.png.
#include "app_internal.hpp"
#include "fullscreen.hpp"
#include "imgui_layer.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <rrc/image.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>

namespace rrc::demo {
namespace {

// Key presses, not key states: a held key toggles once.
class KeyEdges {
public:
    bool pressed(GLFWwindow* window, int key) {
        const bool down = glfwGetKey(window, key) == GLFW_PRESS;
        bool& was = down_[static_cast<size_t>(key) % down_.size()];
        const bool edge = down && !was;
        was = down;
        return edge;
    }

private:
    std::array<bool, GLFW_KEY_LAST + 1> down_{};
};

// GLFW reports the wheel only through a callback; ImGui's backend chains to this one.
struct WheelState {
    double steps = 0.0;
};
void onScroll(GLFWwindow* window, double, double y) {
    if (auto* wheel = static_cast<WheelState*>(glfwGetWindowUserPointer(window))) wheel->steps += y;
}

// Installs onScroll; removes it again after ImGui (declared later, destroyed earlier) has
// restored it as the callback it chained to.
struct WheelHook {
    GLFWwindow* window;
    WheelHook(GLFWwindow* w, WheelState* state) : window(w) {
        glfwSetWindowUserPointer(window, state);
        glfwSetScrollCallback(window, onScroll);
    }
    ~WheelHook() {
        glfwSetScrollCallback(window, nullptr);
        glfwSetWindowUserPointer(window, nullptr);
    }
    WheelHook(const WheelHook&) = delete;
    WheelHook& operator=(const WheelHook&) = delete;
};

} // namespace

Result<void> Runner::writeWindowImage(const std::string& dir, const std::string& name, int width, int height) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    const std::string path = (std::filesystem::path(dir) / (name + "_window.png")).string();
    if (auto r = writeImage(path, readFramebuffer(0, GL_BACK, width, height)); !r) return r;
    written_["window_png"] = path;
    return {};
}

Result<void> Runner::runWindowed() {
    GLFWwindow* window = app_.window_;
    WheelState wheel;
    const WheelHook hook(window, &wheel);   // before ImGui, which chains to it
    auto blitter = Blitter::create(app_.shaders_);
    if (!blitter) return blitter.error();
    auto gui = ImGuiLayer::create(window);
    if (!gui) return gui.error();
    ImGuiLayer& overlay = *gui.value();

    const Options& o = app_.options_;
    FlyController controller;
    KeyEdges keys;
    glm::dvec2 cursor;
    glfwGetCursorPos(window, &cursor.x, &cursor.y);
    auto last = std::chrono::steady_clock::now();
    double time = 0.0, demoMs = 0.0;
    bool paused = false;
    for (int frame = 0; !glfwWindowShouldClose(window) && (!o.framesGiven || frame < o.warmup + o.frames);) {
        glfwPollEvents();
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
        if (fbWidth <= 0 || fbHeight <= 0) { glfwWaitEventsTimeout(0.1); continue; }   // minimised
        if (auto r = resize(fbWidth, fbHeight); !r) return r;
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::min(std::chrono::duration<double>(now - last).count(), 0.25);
        last = now;

        if (!overlay.wantsKeyboard()) {
            if (keys.pressed(window, GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window, GLFW_TRUE);
            if (keys.pressed(window, GLFW_KEY_M)) app_.mode_ = app_.mode_ == Mode::Brute ? Mode::Cached : Mode::Brute;
            if (keys.pressed(window, GLFW_KEY_V)) app_.showVisualization_ = !app_.showVisualization_;
            if (keys.pressed(window, GLFW_KEY_C)) app_.followPath_ = true;
            if (keys.pressed(window, GLFW_KEY_SPACE)) paused = !paused;
        }
        glm::dvec2 position;
        glfwGetCursorPos(window, &position.x, &position.y);
        const bool keyboard = !overlay.wantsKeyboard();
        auto key = [&](int k) { return keyboard && glfwGetKey(window, k) == GLFW_PRESS; };
        const ControllerInput input{
            .forward = key(GLFW_KEY_W), .back = key(GLFW_KEY_S), .left = key(GLFW_KEY_A), .right = key(GLFW_KEY_D),
            .up = key(GLFW_KEY_E), .down = key(GLFW_KEY_Q),
            .fast = key(GLFW_KEY_LEFT_SHIFT) || key(GLFW_KEY_RIGHT_SHIFT),
            .dragging = !overlay.wantsMouse() && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS,
            .mouseDelta = position - cursor,
            .scroll = overlay.wantsMouse() ? 0.0 : wheel.steps,
            .dt = dt};
        cursor = position;
        wheel.steps = 0.0;
        const bool steering = input.forward || input.back || input.left || input.right || input.up || input.down ||
                              (input.dragging && (input.mouseDelta.x != 0.0 || input.mouseDelta.y != 0.0));
        if (steering && app_.followsPath()) app_.followPath_ = false;   // the user takes over
        if (steering) {
            controller.attach(app_.camera_);
            controller.update(app_.camera_, input);
        } else if (input.scroll != 0.0) {
            controller.update(app_.camera_, input);   // speed only
        }
        if (!paused) time += dt;

        demoMs = timedFrame({.frame = frame, .time = time, .dt = dt, .warmup = frame < o.warmup});
        if (desc_.stats) stats_ = desc_.stats(app_);
        const Outputs outputs = desc_.outputs ? desc_.outputs(app_) : Outputs{};

        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fbWidth, fbHeight);
        for (GLenum cap : {GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST, GL_STENCIL_TEST}) glDisable(cap);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        const GLuint shown = app_.showVisualization_ && outputs.visualization ? outputs.visualization : outputs.color;
        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (shown) blitter.value().draw(shown);

        overlay.beginFrame();
        const ImGuiIO& io = ImGui::GetIO();
        ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowBgAlpha(0.75f);
        ImGui::Begin(desc_.name.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::Text("%.1f fps (%.2f ms), demo frame %.2f ms", io.Framerate, 1000.0f / std::max(io.Framerate, 1e-3f), demoMs);
        ImGui::Text("%s %dx%d, %s", std::string(backendName(app_.context_->backend())).c_str(), app_.width_,
                    app_.height_, app_.context_->renderer().c_str());
        int mode = app_.mode_ == Mode::Brute ? 0 : 1;
        ImGui::RadioButton("brute", &mode, 0);
        ImGui::SameLine();
        ImGui::RadioButton("cached (M)", &mode, 1);
        app_.mode_ = mode == 0 ? Mode::Brute : Mode::Cached;
        if (outputs.visualization) ImGui::Checkbox("hit/miss view (V)", &app_.showVisualization_);
        if (app_.path_) ImGui::Checkbox("camera path (C)", &app_.followPath_);
        ImGui::Checkbox("pause clock (Space)", &paused);
        if (!stats_.empty()) ImGui::Separator();
        for (const auto& [name, value] : stats_) ImGui::Text("%s: %.4g", name.c_str(), value);
        if (desc_.gui) {
            ImGui::Separator();
            desc_.gui(app_);
        }
        ImGui::TextDisabled("WASD/QE move, drag to look, wheel: speed %.2g m/s", controller.speed);
        ImGui::End();
        overlay.endFrame();
        ++guiFrames_;
        if (!o.out.empty() && o.framesGiven && frame + 1 == o.warmup + o.frames) {
            if (auto r = writeWindowImage(o.out, desc_.name, fbWidth, fbHeight); !r) return r;
        }
        glfwSwapBuffers(window);
        ++frame;
    }
    return {};
}

} // namespace rrc::demo
