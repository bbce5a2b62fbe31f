// The GL entry points rrc uses: glad2 (generated at build time), loaded through whichever
// provider's getProcAddress is current (EGL, OSMesa or GLFW), never linked from libGL.
#pragma once
#include <glad/gl.h>

#include <rrc/result.hpp>

namespace rrc {

// Loads every GL 4.5 core entry point through `getProcAddress`; fails below GL 4.5.
Result<void> loadGL(GLADloadfunc getProcAddress);

} // namespace rrc
