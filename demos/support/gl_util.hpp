// Small GL conveniences every demo renderer needs: an immutable 2D texture and uniforms set by
// name (a no-op for a name the program does not use, so one draw loop serves every pass).
#pragma once
#include <rrc/gl_object.hpp>

#include <glm/mat4x4.hpp>

namespace rrc::demo {

// One level of `format`. `filter` (min and mag) and `wrap` (S and T) are left at GL's defaults
// when 0.
inline Texture makeTexture2D(GLenum format, int width, int height, GLenum filter = 0, GLenum wrap = 0) {
    Texture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, width, height);
    if (filter) {
        glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
        glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    }
    if (wrap) {
        glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
        glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    }
    return t;
}

inline void setUniform(GLuint program, const char* name, const glm::mat4& m) {
    if (const GLint l = glGetUniformLocation(program, name); l >= 0) glProgramUniformMatrix4fv(program, l, 1, GL_FALSE, &m[0][0]);
}

inline void setUniform(GLuint program, const char* name, float v) {
    if (const GLint l = glGetUniformLocation(program, name); l >= 0) glProgramUniform1f(program, l, v);
}

} // namespace rrc::demo
