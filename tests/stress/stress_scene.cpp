#include "stress_scene.hpp"

#include <cstdio>
#include <cstring>

namespace rrc::test {
namespace {

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

void setVec4(GLuint program, const char* name, const glm::vec4& v) {
    if (const GLint l = glGetUniformLocation(program, name); l >= 0) glProgramUniform4fv(program, l, 1, &v[0]);
}

} // namespace

StressScene::StressScene(const Cache& cache, const std::string& body, std::vector<Define> extra)
    : QuadScene(cache, std::string(kFragmentHead) + body + kFragmentMain, std::move(extra)) {}

void StressScene::setFrameUniforms(GLuint program, uint32_t frame) const {
    if (const GLint l = glGetUniformLocation(program, "u_frame"); l >= 0) glProgramUniform1ui(program, l, frame);
    setVec4(program, "u_params", params);
    setVec4(program, "u_params2", params2);
}

bool StressScene::frame(Cache& cache, ControlFlow flow, const glm::dmat4& view, const glm::dmat4& projection,
                        std::span<const Object> objects, FrameDesc f) {
    f.view = view;
    f.projection = projection;
    return renderFrame(cache, flow, objects, f);
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
