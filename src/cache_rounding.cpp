// probeStoreRounding: how a fragment shader's float output is rounded when stored into a colour
// format, measured by rendering values that lie between two representable neighbours.
#include "cache_impl.hpp"

#include <cmath>
#include <string>

namespace rrc {
namespace {

const char* kProbeVertex = R"(#version 450 core
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* kProbeFragment = R"(#version 450 core
uniform float u_values[12];
out vec4 o_color;
void main() { o_color = vec4(u_values[min(int(gl_FragCoord.y) * 4 + int(gl_FragCoord.x), 11)]); }
)";

struct ProbeGrid {
    bool exact;        // nothing to measure
    bool isSigned;     // negative values are representable
    float base[3];     // representable values low, in the middle and high in the range
    float step[3];     // the distance from each to its upper neighbour
};

bool probeGrid(GLenum format, ProbeGrid& grid) {
    auto unorm = [&](float n) {
        grid = {false, false, {std::round(0.1f * n) / n, std::round(0.5f * n) / n, std::round(0.9f * n) / n}, {1 / n, 1 / n, 1 / n}};
    };
    auto small = [&](bool isSigned, int mantissaBits) {
        grid = {false, isSigned, {0.01171875f, 1.0f, 1000.0f},
                {std::ldexp(1.0f, -7 - mantissaBits), std::ldexp(1.0f, -mantissaBits), std::ldexp(1.0f, 9 - mantissaBits)}};
    };
    switch (format) {
    case GL_RGBA8: unorm(255.0f); return true;
    case GL_RGB10_A2: unorm(1023.0f); return true;
    case GL_RGBA16F: case GL_RG16F: case GL_R16F: small(true, 10); return true;
    case GL_R11F_G11F_B10F: small(false, 6); return true;   // red: 6 mantissa bits
    case GL_RGBA32F: case GL_RG32F: case GL_R32F: case GL_R32UI: case GL_RG32UI: case GL_RGBA32UI:
        grid = {true, true, {}, {}};
        return true;
    default: return false;
    }
}

} // namespace

std::string_view storeRoundingName(StoreRounding rounding) {
    switch (rounding) {
    case StoreRounding::Exact: return "exact";
    case StoreRounding::Nearest: return "nearest";
    case StoreRounding::TowardZero: return "toward-zero";
    case StoreRounding::Other: return "other";
    }
    return "?";
}

Result<StoreRounding> probeStoreRounding(GLenum format) {
    ProbeGrid grid{};
    if (!probeGrid(format, grid))
        return fail(LogId::CacheInvalidDesc, "probeStoreRounding: format " + std::to_string(format) + " is not a payload format");
    if (grid.exact) return StoreRounding::Exact;

    ShaderLibrary library;
    library.add("rrc/internal/probe.vert", kProbeVertex);
    library.add("rrc/internal/probe.frag", kProbeFragment);
    auto program = buildProgram({.vertex = "rrc/internal/probe.vert", .fragment = "rrc/internal/probe.frag"}, library);
    if (!program) return program.error();
    Texture target = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(target.id(), 1, format, 4, 3);
    Framebuffer framebuffer = createFramebuffer();
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    if (auto r = checkFramebuffer(framebuffer, "probeStoreRounding"); !r) return r.error();
    VertexArray vao = createVertexArray();

    // Per base (one row each): three quarters and one quarter of the way to the upper
    // neighbour, then the same negated.
    float values[12];
    for (int b = 0; b < 3; ++b) {
        values[4 * b + 0] = grid.base[b] + 0.75f * grid.step[b];
        values[4 * b + 1] = grid.base[b] + 0.25f * grid.step[b];
        values[4 * b + 2] = -values[4 * b + 0];
        values[4 * b + 3] = -values[4 * b + 1];
    }
    glProgramUniform1fv(program.value().id(), glGetUniformLocation(program.value().id(), "u_values"), 12, values);

    GLint previousFramebuffer = 0, previousProgram = 0, previousVao = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &previousVao);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, 4, 3);
    glUseProgram(program.value().id());
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(static_cast<GLuint>(previousVao));
    restoreProgram(previousProgram);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));

    float read[48] = {};
    glGetTextureImage(target.id(), 0, GL_RGBA, GL_FLOAT, sizeof(read), read);
    // Each value read back as a whole number of steps away from its (signed) base value; one
    // answer only when every base agrees (llvmpipe's GL_RGB10_A2 stores about floor(x * 1024), which
    // rounds down low in the range and up high in it: Other).
    int nearest = 0, towardZero = 0;
    for (int b = 0; b < 3; ++b) {
        auto steps = [&](int i) {
            const float base = i < 2 ? grid.base[b] : -grid.base[b];
            return std::lround(std::fabs(read[4 * (4 * b + i)] - base) / grid.step[b]);
        };
        const bool negativeTowardZero = !grid.isSigned || (steps(2) == 0 && steps(3) == 0);
        const bool negativeNearest = !grid.isSigned || (steps(2) == 1 && steps(3) == 0);
        nearest += steps(0) == 1 && steps(1) == 0 && negativeNearest;
        towardZero += steps(0) == 0 && steps(1) == 0 && negativeTowardZero;
    }
    if (nearest == 3) return StoreRounding::Nearest;
    if (towardZero == 3) return StoreRounding::TowardZero;
    return StoreRounding::Other;
}

} // namespace rrc
