// The GL side of the scene layer: uploads draw the expected pixels (a triangle's half of the
// target, texture orientation and sRGB storage), skinned vertices computed on the GPU from the
// joint SSBOs match the CPU, and nothing raises a GL error or leaks (GLTest checks both).
#include "scene_fixtures.hpp"
#include "support/draw.hpp"
#include "support/gl_test.hpp"

#include "gpu_scene.hpp"

#include <rrc/image.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace rrc::test {
namespace {

using namespace rrc::scene;

const char* kVert = R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_mvp;
out vec2 v_uv;
void main() { gl_Position = u_mvp * vec4(a_position, 1.0); v_uv = a_uv; }
)";
const char* kFrag = R"(#version 450 core
layout(binding = 0) uniform sampler2D u_baseColor;
uniform vec4 u_factor;
uniform bool u_textured;
in vec2 v_uv;
out vec4 o_color;
void main() { o_color = u_factor * (u_textured ? texture(u_baseColor, v_uv) : vec4(1.0)); }
)";

// Writes each vertex's skinned position (current and previous joints) into an SSBO.
const char* kSkinCaptureVert = R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 4) in uvec4 a_joints;
layout(location = 5) in vec4 a_weights;
layout(std430, binding = 3) readonly buffer Joints { mat4 joints[]; };
layout(std430, binding = 4) readonly buffer PrevJoints { mat4 prevJoints[]; };
layout(std430, binding = 6) writeonly buffer Out { vec4 skinned[]; };
void main() {
    mat4 s = a_weights.x * joints[a_joints.x] + a_weights.y * joints[a_joints.y] +
             a_weights.z * joints[a_joints.z] + a_weights.w * joints[a_joints.w];
    mat4 p = a_weights.x * prevJoints[a_joints.x] + a_weights.y * prevJoints[a_joints.y] +
             a_weights.z * prevJoints[a_joints.z] + a_weights.w * prevJoints[a_joints.w];
    skinned[2 * gl_VertexID] = s * vec4(a_position, 1.0);
    skinned[2 * gl_VertexID + 1] = p * vec4(a_position, 1.0);
    gl_Position = vec4(0.0);
}
)";
const char* kEmptyFrag = R"(#version 450 core
void main() {}
)";

class SceneGpu : public GLTest {
protected:
    // Draws every item of `gpu` with the flat/textured program and projection `proj`.
    void drawAll(const GpuScene& gpu, const SceneState& state, const Target& target, const glm::dmat4& proj, int* draws = nullptr) {
        Program p = program("scene/test.vert", kVert, "scene/test.frag", kFrag);
        glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
        glViewport(0, 0, target.width, target.height);
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glUseProgram(p.id());
        gpu.forEachDraw(state, [&](const DrawItem& item) {
            const glm::mat4 mvp(proj * item.world);
            glProgramUniformMatrix4fv(p.id(), glGetUniformLocation(p.id(), "u_mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
            const glm::vec4 factor = item.material ? item.material->baseColorFactor : glm::vec4(1.0f);
            glProgramUniform4fv(p.id(), glGetUniformLocation(p.id(), "u_factor"), 1, glm::value_ptr(factor));
            glProgramUniform1i(p.id(), glGetUniformLocation(p.id(), "u_textured"), item.baseColorTexture != 0);
            glBindTextureUnit(0, item.baseColorTexture);
            item.draw();
            if (draws) ++*draws;
        });
        glBindTextureUnit(0, 0);
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
};

TEST_F(SceneGpu, TriangleCoversItsHalfOfTheTarget) {
    TempDir dir;
    auto loaded = loadScene(dir.write("tri.gltf", triangleDocument()));
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const Scene& s = loaded.value();
    auto gpu = GpuScene::upload(s);
    ASSERT_TRUE(gpu.ok());
    SceneState state(s);
    Target target = makeTarget(64, 64, GL_RGBA16F);
    int draws = 0;
    // The unit square [0,1]^2 fills the target, so the triangle (0,0) (1,0) (0,1) covers x + y < 1.
    drawAll(gpu.value(), state, target, glm::ortho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0), &draws);
    EXPECT_EQ(draws, 1);
    std::vector<glm::vec4> pixels(64 * 64);
    glGetTextureImage(target.color.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(glm::vec4)), pixels.data());
    int wrong = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float sum = (float(x) + 0.5f) / 64.0f + (float(y) + 0.5f) / 64.0f;
            if (std::abs(sum - 1.0f) < 1.5f / 64.0f) continue;  // edge pixels: either is fine
            const glm::vec4 expected = sum < 1.0f ? glm::vec4(0.8f, 0.1f, 0.1f, 1.0f) : glm::vec4(0.0f);
            if (glm::any(glm::greaterThan(glm::abs(pixels[size_t(y * 64 + x)] - expected), glm::vec4(1e-3f)))) ++wrong;
        }
    EXPECT_EQ(wrong, 0);
}

// A 2x2 texture (top row red, green; bottom row blue, white) on a full-target quad whose uv (0,0)
// is the top-left corner, as glTF defines it: the top-left quadrant of the image must be red.
TEST_F(SceneGpu, BaseColorTextureIsSrgbMipmappedAndUpright) {
    TempDir dir;
    OIIO::ImageBuf image(OIIO::ImageSpec(2, 2, 4, OIIO::TypeDesc::UINT8));
    const float texels[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    for (int i = 0; i < 4; ++i) image.setpixel(i % 2, i / 2, texels[i]);
    ASSERT_TRUE(writeImage((dir.path() / "checker.png").string(), image).ok());
    nlohmann::json doc = triangleDocument();
    doc["buffers"] = doc["bufferViews"] = doc["accessors"] = nlohmann::json::array();
    const int position = addAccessor(doc, std::vector<float>{-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0}, kFloat, "VEC3", 4);
    const int uv = addAccessor(doc, std::vector<float>{0, 1, 1, 1, 0, 0, 1, 0}, kFloat, "VEC2", 4);
    const int indices = addAccessor(doc, std::vector<uint16_t>{0, 1, 2, 2, 1, 3}, kUShort, "SCALAR", 6);
    const nlohmann::json primitive = {{"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv}}}, {"indices", indices}, {"material", 0}};
    doc["meshes"] = nlohmann::json::array({nlohmann::json{{"primitives", nlohmann::json::array({primitive})}}});
    doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
    doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9728}}};  // NEAREST
    doc["images"] = {{{"uri", "checker.png"}}};
    auto loaded = loadScene(dir.write("quad.gltf", doc));
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    auto gpu = GpuScene::upload(loaded.value());
    ASSERT_TRUE(gpu.ok());

    const GLuint texture = gpu.value().texture(0, true);
    ASSERT_NE(texture, 0u);
    GLint format = 0, levels = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    EXPECT_EQ(format, GL_SRGB8_ALPHA8);
    EXPECT_EQ(levels, 2);  // 2x2 and 1x1

    SceneState state(loaded.value());
    Target target = makeTarget(32, 32, GL_RGBA16F);
    drawAll(gpu.value(), state, target, glm::dmat4(1.0));
    // readPixel uses GL coordinates: y = 0 is the bottom row.
    EXPECT_EQ(readPixel(target, 4, 28), glm::vec4(1, 0, 0, 1));   // top-left: red
    EXPECT_EQ(readPixel(target, 28, 28), glm::vec4(0, 1, 0, 1));  // top-right: green
    EXPECT_EQ(readPixel(target, 4, 4), glm::vec4(0, 0, 1, 1));    // bottom-left: blue
    EXPECT_EQ(readPixel(target, 28, 4), glm::vec4(1, 1, 1, 1));   // bottom-right: white
}

TEST_F(SceneGpu, TempleUploadsAndDrawsEveryInstance) {
    auto loaded = loadScene(std::string(RRC_SCENE_ASSETS) + "/temple.glb");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const Scene& s = loaded.value();
    auto gpu = GpuScene::upload(s);
    ASSERT_TRUE(gpu.ok());
    const GLuint normal = gpu.value().texture(s.materials[0].normalTexture.texture, false);
    ASSERT_NE(normal, 0u);
    GLint format = 0;
    glGetTextureLevelParameteriv(normal, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    EXPECT_EQ(format, GL_RGBA8);
    // Every primitive of every mesh node below the roots is one draw.
    size_t expected = 0;
    std::vector<uint32_t> stack = s.roots;
    while (!stack.empty()) {
        const Node& n = s.nodes[stack.back()];
        stack.pop_back();
        stack.insert(stack.end(), n.children.begin(), n.children.end());
        if (n.mesh >= 0) expected += s.meshes[size_t(n.mesh)].primitives.size();
    }
    SceneState state(s);
    Target target = makeTarget(64, 48, GL_RGBA16F);
    const glm::dmat4 view = glm::lookAt(glm::dvec3(30, 6, 62), glm::dvec3(0, 7, 8), glm::dvec3(0, 1, 0));
    int draws = 0;
    glEnable(GL_DEPTH_TEST);
    drawAll(gpu.value(), state, target, glm::perspective(0.9, 64.0 / 48.0, 0.1, 1000.0) * view, &draws);
    glDisable(GL_DEPTH_TEST);
    EXPECT_EQ(size_t(draws), expected);
    EXPECT_GT(expected, 74u);  // the 74 columns alone
    EXPECT_NE(readPixel(target, 32, 24), glm::vec4(0.0f));  // the temple fills the view's centre
}

// Runs the character's animation for two frames and checks on the GPU that both joint SSBOs
// skin every vertex where the CPU puts it (anchor-relative), through the VAO's joint and weight
// attributes.
TEST_F(SceneGpu, SkinnedVerticesMatchTheCpuForBothFrames) {
    auto loaded = loadScene(std::string(RRC_SCENE_ASSETS) + "/character.glb");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const Scene& s = loaded.value();
    auto uploaded = GpuScene::upload(s);
    ASSERT_TRUE(uploaded.ok());
    GpuScene& gpu = uploaded.value();
    SceneState state(s);
    const Animation& run = s.animations[0];
    state.advance(run.start + 0.1, &run);
    state.advance(run.start + 0.3, &run);
    gpu.updateJoints(state);

    std::vector<glm::mat4> current(s.skins[0].joints.size()), previous(current.size());
    const GLsizeiptr bytes = GLsizeiptr(current.size() * sizeof(glm::mat4));
    glGetNamedBufferSubData(gpu.jointBuffer(0), 0, bytes, current.data());
    glGetNamedBufferSubData(gpu.previousJointBuffer(0), 0, bytes, previous.data());
    EXPECT_EQ(current, state.skin(0).relative);
    EXPECT_EQ(previous, state.previousSkin(0).relative);
    EXPECT_NE(current, previous);

    Program capture = program("scene/capture.vert", kSkinCaptureVert, "scene/empty.frag", kEmptyFrag);
    // EGL surfaceless has no complete default framebuffer: draw (discarded) into a target.
    Target target = makeTarget(1, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    int skinnedDraws = 0;
    gpu.forEachDraw(state, [&](const DrawItem& item) {
        if (item.skin < 0) return;
        ++skinnedDraws;
        const Primitive& p = s.meshes[item.mesh].primitives[item.primitive];
        Buffer out = createBuffer();
        glNamedBufferStorage(out.id(), GLsizeiptr(p.positions.size() * 2 * sizeof(glm::vec4)), nullptr, 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, out.id());
        glUseProgram(capture.id());
        glEnable(GL_RASTERIZER_DISCARD);
        glBindVertexArray(item.vertexArray);
        glDrawArrays(GL_POINTS, 0, GLsizei(p.positions.size()));
        glBindVertexArray(0);
        glDisable(GL_RASTERIZER_DISCARD);
        glUseProgram(0);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<glm::vec4> skinned(p.positions.size() * 2);
        glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(skinned.size() * sizeof(glm::vec4)), skinned.data());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, 0);
        double worst = 0.0;
        for (size_t v = 0; v < p.positions.size(); ++v) {
            const glm::dvec4 w(p.weights[v]);
            const glm::dvec3 now = skinPoint(state.skin(0), p.positions[v], p.joints[v], w);
            const glm::dvec3 before = skinPoint(state.previousSkin(0), p.positions[v], p.joints[v], w);
            // GPU results are relative to the anchor; item.world / previousWorld put them back.
            worst = std::max(worst, glm::length(glm::dvec3(item.world * glm::dvec4(glm::dvec3(skinned[2 * v]), 1.0)) - now));
            worst = std::max(worst, glm::length(glm::dvec3(item.previousWorld * glm::dvec4(glm::dvec3(skinned[2 * v + 1]), 1.0)) - before));
        }
        EXPECT_LT(worst, 1e-4) << "mesh " << item.mesh << " primitive " << item.primitive;
    });
    EXPECT_GT(skinnedDraws, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kJointsBinding, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrevJointsBinding, 0);
}

} // namespace
} // namespace rrc::test
