#include "cache_scene.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

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

const char* kFragment = R"(#version 450 core
#ifdef PASS_MISS
layout(early_fragment_tests) in;
#endif
#include <rrc/lookup.frag>
#include <rrc/blend.glsl>
layout(location = 0) out vec4 o_payload;
layout(std430, binding = 5) buffer MissCounter { uint missFragments; };
in vec3 v_world;
uniform uint u_forceMiss;
uniform uint u_frame;
uniform float u_sampleOffset;

vec4 freshSample() {
#if SHADING == 0 && defined(RRC_DEPTH_IN_PAYLOAD)
    vec4 s = vec4(v_world, 1.0);
    s.RRC_DEPTH_CHANNEL = rrc_currentLinearDepth();   // the lookup's cached depth
    return s;
#elif SHADING == 0
    return vec4(v_world, 1.0);
#else
    // Seeded uniform noise per pixel and frame, mean 0.5, variance 1/12.
    float n = rrc_hashToUnit(rrc_hash(uvec3(uvec2(gl_FragCoord.xy), u_frame + 17u)));
    return vec4(n + u_sampleOffset, n, n, 1.0);
#endif
}

vec4 combine(rrc_Lookup l, vec4 cached) {
#if SHADING == 0
    return cached;
#else
    return rrc_blend(cached, freshSample(), l.age, rrc_tolerance.w);
#endif
}

void main() {
    rrc_Lookup l = rrc_lookup(u_forceMiss != 0u);
#if defined(PASS_LOOKUP)
    if (!l.hit) discard;
    o_payload = combine(l, rrc_fetchPayload0(l));
#elif defined(PASS_MISS)
    // Early tests: count only fragments the depth test lets through (side effects would
    // otherwise make the shader run before the test).
    atomicAdd(missFragments, 1u);
    o_payload = rrc_firstSample(freshSample());
#else
    o_payload = l.hit ? combine(l, rrc_fetchPayload0(l)) : rrc_firstSample(freshSample());
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
void setUint(GLuint program, const char* name, uint32_t v) {
    if (const GLint l = glGetUniformLocation(program, name); l >= 0) glProgramUniform1ui(program, l, v);
}

} // namespace

glm::dmat4 Camera::view() const { return glm::lookAt(eye, target, glm::dvec3(0, 1, 0)); }

glm::dmat4 Camera::projection(double aspect, bool reversedZ) const {
    return reversedZ ? perspectiveReversedZ(fovy, aspect, near, far) : perspectiveStandard(fovy, aspect, near, far);
}

glm::dmat4 quadAt(glm::dvec3 center, glm::dvec2 halfSize) {
    return glm::scale(glm::translate(glm::dmat4(1.0), center), glm::dvec3(halfSize, 1.0));
}

QuadScene::QuadScene(const Cache& cache, const std::string& fragment, std::vector<Define> defines) {
    library_.add("test/scene.vert", kVertex);
    library_.add("test/scene.frag", fragment);
    library_.add("test/depth.frag", kDepthOnly);
    library_.add("test/resolve.vert", kResolveVertex);
    library_.add("test/resolve.frag", kResolveFragment);
    const std::vector<Define> cacheDefines = cache.defines();
    defines.insert(defines.begin(), cacheDefines.begin(), cacheDefines.end());
    auto with = [&](const char* pass) { auto d = defines; d.push_back({pass}); return d; };
    lookup_ = build(library_, "test/scene.vert", "test/scene.frag", with("PASS_LOOKUP"));
    miss_ = build(library_, "test/scene.vert", "test/scene.frag", with("PASS_MISS"));
    shade_ = build(library_, "test/scene.vert", "test/scene.frag", defines);
    depthOnly_ = build(library_, "test/scene.vert", "test/depth.frag", defines);
    resolve_ = build(library_, "test/resolve.vert", "test/resolve.frag", {});
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

void QuadScene::drawObjects(const Cache& cache, GLuint program, std::span<const Object> objects, uint32_t frame) const {
    glUseProgram(program);
    glBindVertexArray(vao_.id());
    setFrameUniforms(program, frame);
    for (const Object& o : objects) {
        const DrawMatrices m = cache.drawMatrices(o.model, o.prevModel);
        setMatrix(program, "u_mvp", m.modelViewProj);
        setMatrix(program, "u_model", glm::mat4(o.model));
        setObjectUniforms(program, o);
        cache.setDrawUniforms(program, m, o.id, o.neverCache);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

bool QuadScene::renderFrame(Cache& cache, ControlFlow flow, std::span<const Object> objects, const FrameDesc& f) {
    if (!cache.beginFrame(f).ok()) return false;
    beforeRender();
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
    EXPECT_TRUE(r.ok());
    cache.endFrame();
    return r.ok();
}

CacheScene::CacheScene(const Cache& cache, Shading shading, std::vector<Define> extra)
    : QuadScene(cache, kFragment, [&] {
          std::vector<Define> d{{"SHADING", shading == Shading::WorldPosition ? "0" : "1"}};
          d.insert(d.end(), extra.begin(), extra.end());
          return d;
      }()) {
    counter_ = createBuffer();
    glNamedBufferStorage(counter_.id(), sizeof(uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void CacheScene::setFrameUniforms(GLuint program, uint32_t frame) const {
    setUint(program, "u_frame", frame);
    if (const GLint l = glGetUniformLocation(program, "u_sampleOffset"); l >= 0) glProgramUniform1f(program, l, sampleOffset);
}

void CacheScene::setObjectUniforms(GLuint program, const Object& o) const {
    setUint(program, "u_forceMiss", o.forceMiss ? 1u : 0u);
}

void CacheScene::beforeRender() {
    const uint32_t zero = 0;
    glClearNamedBufferData(counter_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, counter_.id());
}

bool CacheScene::frame(Cache& cache, ControlFlow flow, const Camera& camera, std::span<const Object> objects,
                       FrameDesc f) {
    const double aspect = static_cast<double>(cache.width()) / cache.height();
    f.view = camera.view();
    f.projection = camera.projection(aspect, cache.desc().reversedZ);
    return renderFrame(cache, flow, objects, f);
}

uint32_t CacheScene::missFragments() const {
    uint32_t n = 0;
    glGetNamedBufferSubData(counter_.id(), 0, sizeof(n), &n);
    return n;
}

namespace {

// The whole of level 0 as `T`s in GL order.
template <class T>
std::vector<T> readWhole(GLuint texture, GLenum format, GLenum type) {
    GLint w = 0, h = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
    std::vector<T> out(static_cast<size_t>(w) * h);
    glGetTextureImage(texture, 0, format, type, static_cast<GLsizei>(out.size() * sizeof(T)), out.data());
    return out;
}

} // namespace

std::vector<glm::vec4> readRGBA(GLuint texture) { return readWhole<glm::vec4>(texture, GL_RGBA, GL_FLOAT); }
std::vector<uint32_t> readUint(GLuint texture) { return readWhole<uint32_t>(texture, GL_RED_INTEGER, GL_UNSIGNED_INT); }
std::vector<float> readDepthTexture(GLuint texture) { return readWhole<float>(texture, GL_DEPTH_COMPONENT, GL_FLOAT); }

} // namespace rrc::test
