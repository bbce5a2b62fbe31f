// What a demo hands to its renderer: one indexed draw per mesh primitive with the model matrix
// now and at cache time (double precision) and a base colour. Scenes from glTF or generated
// geometry both produce this list.
#pragma once
#include <rrc/gl_object.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <span>

namespace rrc::demo {

struct DrawCall {
    GLuint vertexArray = 0;       // attributes: 0 position, 1 normal (2 uv0, 3 tangent, 4 joints, 5 weights)
    GLsizei indexCount = 0;
    GLenum indexType = GL_UNSIGNED_INT;
    glm::dmat4 model{1.0};
    glm::dmat4 prevModel{1.0};
    glm::vec4 baseColor{1.0f};
    uint32_t objectId = 0;
};

} // namespace rrc::demo
