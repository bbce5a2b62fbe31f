// Compiles Dear ImGui's GLFW backend from Debian's libimgui-dev example sources (path set by
// CMake in RRC_IMGUI_BACKEND_SOURCE). GLFW_INCLUDE_NONE keeps <GL/gl.h> out: GL goes through glad.
#define GLFW_INCLUDE_NONE
#include RRC_IMGUI_BACKEND_SOURCE
