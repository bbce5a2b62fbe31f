#include "draw.hpp"

#include <gtest/gtest.h>

namespace rrc::test {

Target makeTarget(int width, int height, GLenum colorFormat) {
    Target t;
    t.width = width;
    t.height = height;
    t.color = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.color.id(), 1, colorFormat, width, height);
    t.depth = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.depth.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
    t.framebuffer = createFramebuffer();
    glNamedFramebufferTexture(t.framebuffer.id(), GL_COLOR_ATTACHMENT0, t.color.id(), 0);
    glNamedFramebufferTexture(t.framebuffer.id(), GL_DEPTH_ATTACHMENT, t.depth.id(), 0);
    EXPECT_TRUE(checkFramebuffer(t.framebuffer, "test target").ok());
    return t;
}

glm::vec4 readPixel(const Target& target, int x, int y) {
    glm::vec4 pixel(-1.0f);
    glGetTextureSubImage(target.color.id(), 0, x, y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof(pixel), &pixel);
    return pixel;
}

float readDepth(const Target& target, int x, int y) {
    float depth = -1.0f;
    glGetTextureSubImage(target.depth.id(), 0, x, y, 0, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, sizeof(depth), &depth);
    return depth;
}

} // namespace rrc::test
