// Small drawing helpers for GL tests: an offscreen RGBA16F/RGBA32F + D32F target and a quad.
#pragma once
#include <rrc/gl_object.hpp>

#include <glm/vec4.hpp>

namespace rrc::test {

struct Target {
    Texture color, depth;
    Framebuffer framebuffer;
    int width = 0, height = 0;
};

Target makeTarget(int width, int height, GLenum colorFormat = GL_RGBA16F);

// One RGBA float pixel (GL coordinates, origin bottom-left) of the target's colour attachment.
glm::vec4 readPixel(const Target& target, int x, int y);
float readDepth(const Target& target, int x, int y);

} // namespace rrc::test
