#include "accumulator.hpp"

namespace rrc::accumulation {

Result<void> Accumulator::init(int width, int height, ShaderLibrary& library) {
    if (!library.find("common/shaders/fullscreen.vert")) library.add(demo::commonShaders());
    auto pass = demo::FullscreenPass::create(library, "accumulation/shaders/accumulate.frag");
    if (!pass) return pass.error();
    pass_ = std::move(pass).value();
    width_ = width;
    height_ = height;
    target_ = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(target_.id(), 1, GL_RGBA32F, width, height);
    framebuffer_ = createFramebuffer();
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, target_.id(), 0);
    return checkFramebuffer(framebuffer_, "accumulation target");
}

void Accumulator::clear() {
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
}

void Accumulator::add(GLuint texture, float weight) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glProgramUniform1f(pass_.program(), glGetUniformLocation(pass_.program(), "u_weight"), weight);
    glBindTextureUnit(0, texture);
    pass_.draw();
    glBindTextureUnit(0, 0);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

} // namespace rrc::accumulation
