// Compiles Dear ImGui's OpenGL3 backend (libimgui-dev example source, path in
// RRC_IMGUI_BACKEND_SOURCE) with glad as its loader instead of its own imgl3w, which would dlopen
// libGL.so.1 and resolve through GLX: wrong under EGL/OSMesa and a second set of GL pointers.
#include <glad/gl.h>
#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM
#include RRC_IMGUI_BACKEND_SOURCE
