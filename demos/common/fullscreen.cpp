// Full-screen triangle pass and the texture blitter built on it. The vertex array is empty: core
// GL needs one bound to draw, the vertex shader needs no attributes.
#include "fullscreen.hpp"

namespace rrc::demo {

Result<FullscreenPass> FullscreenPass::create(const ShaderLibrary& library, const std::string& fragment,
                                              std::vector<Define> defines) {
    auto program = buildProgram({.vertex = "common/shaders/fullscreen.vert", .fragment = fragment,
                                 .defines = std::move(defines)}, library);
    if (!program) return program.error();
    FullscreenPass pass;
    pass.program_ = std::move(program).value();
    pass.vao_ = createVertexArray();
    return pass;
}

void FullscreenPass::draw() const {
    glUseProgram(program_.id());
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

Result<Blitter> Blitter::create(const ShaderLibrary& library) {
    auto pass = FullscreenPass::create(library, "common/shaders/blit.frag");
    if (!pass) return pass.error();
    Blitter blitter;
    blitter.pass_ = std::move(pass).value();
    return blitter;
}

void Blitter::draw(GLuint texture, float scale, int channel) const {
    glBindTextureUnit(0, texture);
    glProgramUniform1f(pass_.program(), 0, scale);
    glProgramUniform1i(pass_.program(), 1, channel);
    pass_.draw();
    glBindTextureUnit(0, 0);
}

} // namespace rrc::demo
