#include "stress_scene.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

namespace rrc::test {
namespace {

const char* kVertex = R"(#version 450 core
#include <rrc/reproject.vert>
layout(location = 0) in vec2 a_corner;
uniform mat4 u_mvp;
uniform mat4 u_model;
out vec3 v_world;
out vec2 v_local;
void main() {
    vec4 local = vec4(a_corner, 0.0, 1.0);
    gl_Position = u_mvp * local;
    v_world = (u_model * local).xyz;
    v_local = a_corner;
    rrc_reproject(local);
}
)";

const char* kFragmentHead = R"(#version 450 core
#ifdef PASS_MISS
layout(early_fragment_tests) in;
#endif
#include <rrc/lookup.frag>
#include <rrc/blend.glsl>
layout(location = 0) out vec4 o_payload;
in vec3 v_world;
in vec2 v_local;
uniform uint u_frame;
uniform vec4 u_params;
uniform vec4 u_params2;
)";

const char* kFragmentMain = R"(
void main() {
    rrc_Lookup l = rrc_lookup();
#if defined(PASS_LOOKUP)
    if (!l.hit) discard;
    o_payload = onHit(l, rrc_fetchPayload0(l));
#elif defined(PASS_MISS)
    o_payload = onMiss();
#else
    o_payload = l.hit ? onHit(l, rrc_fetchPayload0(l)) : onMiss();
#endif
    rrc_writeCache(l);
}
)";

const char* kDepthOnly = R"(#version 450 core
void main() {}
)";

const char* kResolveVertex = R"(#version 450 core
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
const char* kResolveFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D u_payload;
out vec4 o_color;
void main() { o_color = texelFetch(u_payload, ivec2(gl_FragCoord.xy), 0); }
)";

Program build(ShaderLibrary& lib, const char* vertex, const char* fragment, std::vector<Define> defines) {
    auto p = buildProgram({.vertex = vertex, .fragment = fragment, .defines = std::move(defines)}, lib);
    EXPECT_TRUE(p.ok()) << (p.ok() ? "" : p.error().message);
    return p.ok() ? std::move(p).value() : Program();
}

void setMatrix(GLuint program, const char* name, const glm::mat4& m) {
    if (const GLint l = glGetUniformLocation(program, name); l >= 0) glProgramUniformMatrix4fv(program, l, 1, GL_FALSE, &m[0][0]);
}
void setVec4(GLuint program, const char* name, const glm::vec4& v) {
    if (const GLint l = glGetUniformLocation(program, name); l >= 0) glProgramUniform4fv(program, l, 1, &v[0]);
}

} // namespace

StressScene::StressScene(const Cache& cache, const std::string& body, std::vector<Define> extra) {
    library_.add("stress/scene.vert", kVertex);
    library_.add("stress/scene.frag", std::string(kFragmentHead) + body + kFragmentMain);
    library_.add("stress/depth.frag", kDepthOnly);
    library_.add("stress/resolve.vert", kResolveVertex);
    library_.add("stress/resolve.frag", kResolveFragment);
    std::vector<Define> defines = cache.defines();
    defines.insert(defines.end(), extra.begin(), extra.end());
    auto with = [&](const char* pass) { auto d = defines; d.push_back({pass}); return d; };
    lookup_ = build(library_, "stress/scene.vert", "stress/scene.frag", with("PASS_LOOKUP"));
    miss_ = build(library_, "stress/scene.vert", "stress/scene.frag", with("PASS_MISS"));
    shade_ = build(library_, "stress/scene.vert", "stress/scene.frag", defines);
    depthOnly_ = build(library_, "stress/scene.vert", "stress/depth.frag", defines);
    resolve_ = build(library_, "stress/resolve.vert", "stress/resolve.frag", {});
    const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    vertices_ = createBuffer();
    glNamedBufferStorage(vertices_.id(), sizeof(corners), corners, 0);
    vao_ = createVertexArray();
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, 2 * sizeof(float));
    glEnableVertexArrayAttrib(vao_.id(), 0);
    glVertexArrayAttribFormat(vao_.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_.id(), 0, 0);
    emptyVao_ = createVertexArray();
}

void StressScene::drawObjects(const Cache& cache, GLuint program, std::span<const Object> objects, uint32_t frame) const {
    glUseProgram(program);
    glBindVertexArray(vao_.id());
    if (const GLint l = glGetUniformLocation(program, "u_frame"); l >= 0) glProgramUniform1ui(program, l, frame);
    setVec4(program, "u_params", params);
    setVec4(program, "u_params2", params2);
    for (const Object& o : objects) {
        const DrawMatrices m = cache.drawMatrices(o.model, o.prevModel);
        setMatrix(program, "u_mvp", m.modelViewProj);
        setMatrix(program, "u_model", glm::mat4(o.model));
        cache.setDrawUniforms(program, m, o.id, o.neverCache);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

bool StressScene::frame(Cache& cache, ControlFlow flow, const glm::dmat4& view, const glm::dmat4& projection,
                        std::span<const Object> objects, FrameDesc f) {
    f.view = view;
    f.projection = projection;
    if (!cache.beginFrame(f).ok()) return false;
    passes.clear();
    if (flow == ControlFlow::ThreePass &&
        (!resolved || cache.width() != resolveWidth_ || cache.height() != resolveHeight_)) {
        resolved = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(resolved.id(), 1, GL_RGBA32F, cache.width(), cache.height());
        resolveFramebuffer_ = createFramebuffer();
        glNamedFramebufferTexture(resolveFramebuffer_.id(), GL_COLOR_ATTACHMENT0, resolved.id(), 0);
        resolveWidth_ = cache.width();
        resolveHeight_ = cache.height();
    }
    if (flow == ControlFlow::ThreePass) glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFramebuffer_.id());
    const auto frameIndex = static_cast<uint32_t>(cache.frame());
    auto r = cache.render(flow, [&](Pass pass) {
        passes.push_back(pass);
        switch (pass) {
        case Pass::DepthPrepass: case Pass::Probe: drawObjects(cache, depthOnly_.id(), objects, frameIndex); break;
        case Pass::Shade: drawObjects(cache, shade_.id(), objects, frameIndex); break;
        case Pass::Lookup: drawObjects(cache, lookup_.id(), objects, frameIndex); break;
        case Pass::Miss: drawObjects(cache, miss_.id(), objects, frameIndex); break;
        case Pass::Resolve:
            glUseProgram(resolve_.id());
            glBindTextureUnit(0, cache.payload(0));
            glBindVertexArray(emptyVao_.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindVertexArray(0);
            glUseProgram(0);
            break;
        }
    });
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    cache.endFrame();
    return r.ok();
}

bool StressScene::frame(Cache& cache, ControlFlow flow, const Camera& camera, std::span<const Object> objects,
                        FrameDesc f) {
    const double aspect = static_cast<double>(cache.width()) / cache.height();
    return frame(cache, flow, camera.view(), camera.projection(aspect, cache.desc().reversedZ), objects, f);
}

long residentKiB() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    long kib = 0;
    while (std::fgets(line, sizeof(line), f))
        if (std::strncmp(line, "VmRSS:", 6) == 0) { kib = std::atol(line + 6); break; }
    std::fclose(f);
    return kib;
}

const char* formatName(GLenum format) {
    switch (format) {
    case GL_RGBA8: return "GL_RGBA8";
    case GL_RGB10_A2: return "GL_RGB10_A2";
    case GL_RGBA16F: return "GL_RGBA16F";
    case GL_RG16F: return "GL_RG16F";
    case GL_R16F: return "GL_R16F";
    case GL_R11F_G11F_B10F: return "GL_R11F_G11F_B10F";
    case GL_RGBA32F: return "GL_RGBA32F";
    case GL_RG32F: return "GL_RG32F";
    case GL_R32F: return "GL_R32F";
    default: return "?";
    }
}

} // namespace rrc::test
