// ImGui context and backend lifetimes. The OpenGL3 backend uses glad (see imgui_backend_opengl3.cpp),
// so it draws through the same entry points the context loaded with glfwGetProcAddress.
#include "imgui_layer.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

namespace rrc::demo {

Result<std::unique_ptr<ImGuiLayer>> ImGuiLayer::create(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    auto layer = std::make_unique<ImGuiLayer>(Key());
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;   // no imgui.ini written into the working directory
    ImGui::StyleColorsDark();
    layer->glfwReady_ = ImGui_ImplGlfw_InitForOpenGL(window, true);
    if (!layer->glfwReady_) return fail(LogId::ContextCreateFailed, "Dear ImGui: GLFW backend init failed");
    layer->openglReady_ = ImGui_ImplOpenGL3_Init("#version 450 core");
    if (!layer->openglReady_) return fail(LogId::ContextCreateFailed, "Dear ImGui: OpenGL3 backend init failed");
    return layer;
}

ImGuiLayer::~ImGuiLayer() {
    if (openglReady_) ImGui_ImplOpenGL3_Shutdown();
    if (glfwReady_) ImGui_ImplGlfw_Shutdown();
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

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

} // namespace rrc::demo
