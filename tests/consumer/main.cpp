// Creates a headless context with an installed rrc, composes a library snippet, clears a texture.
#include <rrc/context.hpp>
#include <rrc/gl_object.hpp>
#include <rrc/shader.hpp>

#include <cstdio>

int main() {
    auto context = rrc::Context::create({.backend = rrc::Backend::Egl});
    if (!context) return 1;
    rrc::Texture texture = rrc::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, GL_RGBA8, 4, 4);
    const float value[4] = {1.0f, 0.0f, 0.0f, 1.0f};
    glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, value);
    unsigned char pixel[4] = {};
    glGetTextureSubImage(texture.id(), 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, pixel);
    rrc::ShaderLibrary library;
    const bool snippets = !rrc::librarySnippets().empty();
    std::printf("consumer: %s, pixel %d %d %d %d, %zu snippets\n", context.value().renderer().c_str(), pixel[0],
                pixel[1], pixel[2], pixel[3], rrc::librarySnippets().size());
    return pixel[0] == 255 && pixel[1] == 0 && snippets && glGetError() == GL_NO_ERROR ? 0 : 1;
}
