#include "procedural.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::demo {
namespace {

// A unit cube [-1,1]^3 with per-face normals.
void unitCube(std::vector<float>& v, std::vector<uint32_t>& i) {
    const glm::vec3 normals[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        const glm::vec3 u = glm::abs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 w = glm::cross(n, u);
        const auto base = static_cast<uint32_t>(v.size() / 6);
        for (auto [a, b] : {std::pair{-1.f, -1.f}, std::pair{1.f, -1.f}, std::pair{1.f, 1.f}, std::pair{-1.f, 1.f}}) {
            const glm::vec3 p = n + a * u + b * w;
            v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
        }
        // Counter-clockwise seen from outside.
        const bool flip = glm::dot(glm::cross(u, w), n) < 0;
        const uint32_t quad[] = {0, 1, 2, 0, 2, 3}, quadFlipped[] = {0, 2, 1, 0, 3, 2};
        for (uint32_t k : flip ? quadFlipped : quad) i.push_back(base + k);
    }
}

} // namespace

MeshBuffers uploadMesh(const std::vector<float>& data, const std::vector<uint32_t>& indices) {
    MeshBuffers m;
    m.vertices = createBuffer();
    glNamedBufferStorage(m.vertices.id(), GLsizeiptr(data.size() * sizeof(float)), data.data(), 0);
    m.indices = createBuffer();
    glNamedBufferStorage(m.indices.id(), GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(), 0);
    m.vertexArray = createVertexArray();
    const GLuint vao = m.vertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, m.vertices.id(), 0, 6 * sizeof(float));
    glVertexArrayElementBuffer(vao, m.indices.id());
    for (GLuint a : {0u, 1u}) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
        glVertexArrayAttribBinding(vao, a, 0);
    }
    m.indexCount = GLsizei(indices.size());
    return m;
}

ProceduralScene makeColonnade(int columns) {
    std::vector<float> v;
    std::vector<uint32_t> i;
    unitCube(v, i);
    ProceduralScene s;
    s.meshes.push_back(uploadMesh(v, i));
    const MeshBuffers& cube = s.meshes.back();
    auto add = [&](glm::dvec3 center, glm::dvec3 halfSize, glm::vec4 color) {
        const glm::dmat4 model = glm::scale(glm::translate(glm::dmat4(1.0), center), halfSize);
        s.draws.push_back({cube.vertexArray.id(), cube.indexCount, GL_UNSIGNED_INT, model, model, color,
                           static_cast<uint32_t>(s.draws.size() + 1)});
    };
    add({0, -0.5, 0}, {40, 0.5, 60}, {0.8f, 0.78f, 0.7f, 1});             // ground
    add({0, 0.4, 0}, {7, 0.4, 4.0 * columns}, {0.95f, 0.93f, 0.88f, 1});  // stylobate
    for (int c = 0; c < columns; ++c)
        for (double x : {-5.0, 5.0})
            add({x, 5.8, -4.0 * columns + 4.0 + 8.0 * c}, {0.7, 5.0, 0.7}, {0.97f, 0.95f, 0.9f, 1});
    add({0, 11.3, 0}, {6.5, 0.5, 4.0 * columns}, {0.9f, 0.88f, 0.82f, 1});  // architrave
    return s;
}

} // namespace rrc::demo
