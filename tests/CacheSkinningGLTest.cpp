// A skinned mesh reprojects correctly when the cache-time (previous) bone matrices are used:
// the payload is the bind-pose position, a label of the surface point that skinning does not
// change, so every hit must return exactly the label of the point now under the pixel.
#include "support/cache_scene.hpp"
#include "support/gl_test.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::test {
namespace {

const char* kSkinnedVert = R"(#version 450 core
#include <rrc/skinning.vert>
layout(location = 0) in vec3 a_position;
layout(location = 1) in uvec4 a_joints;
layout(location = 2) in vec4 a_weights;
uniform mat4 u_mvp;
out vec3 v_bind;
void main() {
    vec4 skinned = rrc_skinAndReproject(vec4(a_position, 1.0), a_joints, a_weights);
    gl_Position = u_mvp * skinned;
    v_bind = a_position;
}
)";

const char* kSkinnedFrag = R"(#version 450 core
#include <rrc/lookup.frag>
in vec3 v_bind;
layout(location = 0) out vec4 o_payload;
void main() {
    rrc_Lookup l = rrc_lookup();
    o_payload = l.hit ? rrc_fetchPayload0(l) : vec4(v_bind, 1.0);
    rrc_writeCache(l);
}
)";

struct Vertex { glm::vec3 position; glm::uvec4 joints; glm::vec4 weights; };

// A strip along x in [-2, 2], 2 high, bound to joint 0 left of x = 0 and joint 1 right of it,
// blended over [-0.5, 0.5].
std::vector<Vertex> strip(int segments) {
    std::vector<Vertex> v;
    for (int i = 0; i <= segments; ++i) {
        const float x = -2.0f + 4.0f * float(i) / float(segments);
        const float w1 = glm::clamp(x + 0.5f, 0.0f, 1.0f);
        for (float y : {-1.0f, 1.0f}) v.push_back({{x, y, 0.0f}, {0, 1, 0, 0}, {1.0f - w1, w1, 0, 0}});
    }
    return v;
}

// Joint 1 rotates about the z axis through the origin by `angle`.
std::vector<glm::mat4> bones(float angle) {
    return {glm::mat4(1.0f), glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0, 0, 1))};
}

class CacheSkinning : public GLTest {};

TEST_F(CacheSkinning, PreviousBoneMatricesReprojectTheSkinnedSurface) {
    const auto vertices = strip(64);
    Buffer vbo = createBuffer();
    glNamedBufferStorage(vbo.id(), GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), 0);
    VertexArray vao = createVertexArray();
    glVertexArrayVertexBuffer(vao.id(), 0, vbo.id(), 0, sizeof(Vertex));
    for (GLuint a : {0u, 1u, 2u}) { glEnableVertexArrayAttrib(vao.id(), a); glVertexArrayAttribBinding(vao.id(), a, 0); }
    glVertexArrayAttribFormat(vao.id(), 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
    glVertexArrayAttribIFormat(vao.id(), 1, 4, GL_UNSIGNED_INT, offsetof(Vertex, joints));
    glVertexArrayAttribFormat(vao.id(), 2, 4, GL_FLOAT, GL_FALSE, offsetof(Vertex, weights));
    Buffer current = createBuffer(), previous = createBuffer();
    for (auto* b : {&current, &previous}) glNamedBufferStorage(b->id(), 2 * sizeof(glm::mat4), nullptr, GL_DYNAMIC_STORAGE_BIT);

    for (bool usePreviousBones : {true, false}) {
        Cache cache = Cache::create({.width = 128, .height = 96, .payloads = {{.format = GL_RGBA32F}}}).value();
        library.add("skin/test.vert", kSkinnedVert);
        library.add("skin/test.frag", kSkinnedFrag);
        Program program = buildProgram({.vertex = "skin/test.vert", .fragment = "skin/test.frag", .defines = cache.defines()}, library).value();
        Camera camera{.eye = {0, 0, 6}, .target = {0, 0, 0}};
        auto drawStrip = [&](Pass) {
            const DrawMatrices m = cache.drawMatrices(glm::dmat4(1.0), glm::dmat4(1.0));
            glUseProgram(program.id());
            glProgramUniformMatrix4fv(program.id(), glGetUniformLocation(program.id(), "u_mvp"), 1, GL_FALSE, &m.modelViewProj[0][0]);
            cache.setDrawUniforms(program.id(), m);
            glBindVertexArray(vao.id());
            glDrawArrays(GL_TRIANGLE_STRIP, 0, GLsizei(vertices.size()));
            glBindVertexArray(0);
            glUseProgram(0);
        };
        BoneHistory history;
        std::vector<glm::vec4> payload;
        std::vector<uint32_t> outcomes;
        for (float angle : {0.0f, 0.25f}) {
            const auto b = bones(angle);
            history.update(b);
            glNamedBufferSubData(current.id(), 0, 2 * sizeof(glm::mat4), history.current().data());
            const auto prev = usePreviousBones ? history.previous() : history.current();
            glNamedBufferSubData(previous.id(), 0, 2 * sizeof(glm::mat4), prev.data());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, current.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, previous.id());
            ASSERT_TRUE(cache.beginFrame({.view = camera.view(), .projection = camera.projection(128.0 / 96.0, true)}).ok());
            ASSERT_TRUE(cache.render(ControlFlow::OnePass, drawStrip).ok());
            cache.endFrame();
        }
        payload = readRGBA(cache.payload(0));
        outcomes = readUint(cache.outcomes());
        // The truth: the same pose rendered with everything missing (fresh labels everywhere).
        cache.invalidate();
        ASSERT_TRUE(cache.beginFrame({.view = camera.view(), .projection = camera.projection(128.0 / 96.0, true)}).ok());
        ASSERT_TRUE(cache.render(ControlFlow::OnePass, drawStrip).ok());
        const auto truth = readRGBA(cache.payload(0));
        size_t hits = 0, wrong = 0, covered = 0;
        for (size_t i = 0; i < truth.size(); ++i) {
            covered += truth[i].a == 1.0f;
            if (outcomes[i] != uint32_t(Outcome::Hit)) continue;
            ++hits;
            wrong += glm::length(glm::vec2(payload[i]) - glm::vec2(truth[i])) > 0.02f;
        }
        std::printf("%s bones: %zu of %zu covered pixels hit, %zu with a wrong surface label\n",
                    usePreviousBones ? "previous" : "current", hits, covered, wrong);
        if (usePreviousBones) {
            EXPECT_GT(hits, covered * 9 / 10);
            EXPECT_EQ(wrong, 0u);
        } else {
            EXPECT_GT(wrong, 100u);   // reprojecting with the current bones fetches other points
        }
    }
}

} // namespace
} // namespace rrc::test
