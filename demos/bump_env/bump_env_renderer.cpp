#include "bump_env_renderer.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace rrc::bump_env {
namespace {

Texture makeTexture(GLenum format, int w, int h) {
    Texture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, w, h);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

void setMat4(GLuint p, const char* name, const glm::mat4& m) {
    if (GLint l = glGetUniformLocation(p, name); l >= 0) glProgramUniformMatrix4fv(p, l, 1, GL_FALSE, &m[0][0]);
}

} // namespace

const char* variantName(Variant v) { return v == Variant::Brute ? "brute" : "amortized"; }

Result<void> BumpEnvRenderer::init(int width, int height, const ShaderLibrary& library, const std::string& assetDir) {
    width_ = width;
    height_ = height;
    // RGBA16F with rrc_storeAmortized (unbiased stochastic rounding) keeps the filter from stalling.
    auto cache = Cache::create({.width = width, .height = height, .payloads = {{.format = GL_RGBA16F}}, .age = true});
    if (!cache) return cache.error();
    cache_ = std::move(cache).value();
    auto defines = cache_.defines();
    defines.push_back({"AMORTIZED"});
    auto brute = buildProgram({.vertex = "bump_env/shaders/sphere.vert", .fragment = "bump_env/shaders/bump_env.frag"}, library);
    auto amortized = buildProgram({.vertex = "bump_env/shaders/sphere.vert", .fragment = "bump_env/shaders/bump_env.frag",
                                   .defines = std::move(defines)}, library);
    auto present = demo::FullscreenPass::create(library, "bump_env/shaders/present.frag");
    if (!brute) return brute.error();
    if (!amortized) return amortized.error();
    if (!present) return present.error();
    brute_ = std::move(brute).value();
    amortized_ = std::move(amortized).value();
    present_ = std::move(present).value();
    auto slopes = loadBumpSlopes(assetDir + "/bump.png");
    if (!slopes) return slopes.error();
    auto environment = loadCubeMap(assetDir + "/env");
    if (!environment) return environment.error();
    slopes_ = std::move(slopes).value();
    environment_ = std::move(environment).value();
    sphere_ = makeSphere(128, 64);
    bruteColor_ = makeTexture(GL_RGBA16F, width, height);
    bruteDepth_ = makeTexture(GL_DEPTH_COMPONENT32F, width, height);
    output_ = makeTexture(GL_RGBA8, width, height);
    bruteFb_ = createFramebuffer();
    glNamedFramebufferTexture(bruteFb_.id(), GL_COLOR_ATTACHMENT0, bruteColor_.id(), 0);
    glNamedFramebufferTexture(bruteFb_.id(), GL_DEPTH_ATTACHMENT, bruteDepth_.id(), 0);
    outputFb_ = createFramebuffer();
    glNamedFramebufferTexture(outputFb_.id(), GL_COLOR_ATTACHMENT0, output_.id(), 0);
    if (auto r = checkFramebuffer(bruteFb_, "bump-env brute-force target"); !r) return r;
    return checkFramebuffer(outputFb_, "bump-env output");
}

void BumpEnvRenderer::drawSphere(GLuint p, const BumpSettings& s, const BumpFrame& frame, bool withCache) const {
    glUseProgram(p);
    glBindTextureUnit(0, slopes_.id());
    glBindTextureUnit(1, environment_.id());
    const ViewState now{frame.view, frame.projection};
    const DrawMatrices m = withCache ? cache_.drawMatrices(frame.model, frame.prevModel)
                                     : composeDrawMatrices(now, now, frame.model, frame.model);
    setMat4(p, "u_mvp", m.modelViewProj);
    setMat4(p, "u_model", glm::mat4(frame.model));
    const glm::vec3 eye(glm::inverse(frame.view)[3]);
    glProgramUniform3fv(p, glGetUniformLocation(p, "u_eye"), 1, &eye[0]);
    glProgramUniform1i(p, glGetUniformLocation(p, "u_grid"), std::clamp(s.grid, 1, 16));
    glProgramUniform1f(p, glGetUniformLocation(p, "u_jitter"), s.jitter ? 1.0f : 0.0f);
    glProgramUniform2ui(p, glGetUniformLocation(p, "u_frameSeed"), frame.frame, s.seed);
    glProgramUniform2f(p, glGetUniformLocation(p, "u_tiles"), 8.0f, 4.0f);
    glProgramUniform1f(p, glGetUniformLocation(p, "u_bumpStrength"), s.bumpStrength);
    if (withCache) cache_.setDrawUniforms(p, m);
    glEnable(GL_CULL_FACE);
    glBindVertexArray(sphere_.vertexArray.id());
    glDrawElements(GL_TRIANGLES, sphere_.indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
    glUseProgram(0);
}

void BumpEnvRenderer::render(Variant variant, const BumpSettings& s, const BumpFrame& frame) {
    if (variant == Variant::Brute) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bruteFb_.id());
        glViewport(0, 0, width_, height_);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(bruteFb_.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferfv(bruteFb_.id(), GL_DEPTH, 0, zero);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        drawSphere(brute_.id(), s, frame, false);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        present(bruteColor_.id(), bruteDepth_.id(), frame);
        return;
    }
    // One shading pass (a convex, culled object has no overdraw to save with a prepass): the
    // lookup pass shades hits and misses alike, so the miss pass has nothing left to draw.
    (void)cache_.beginFrame({.view = frame.view, .projection = frame.projection, .lambda = s.lambda, .objectsMoved = true,
                             .depthPrepass = false, .skipEmptyMissPass = false});
    bool shadedAll = false;
    (void)cache_.render(ControlFlow::TwoPass, [&](Pass pass) {
        if (pass == Pass::Lookup || (pass == Pass::Miss && !shadedAll)) drawSphere(amortized_.id(), s, frame, true);
        if (pass == Pass::Lookup) shadedAll = true;
    });
    cache_.endFrame();
    present(cache_.payload(0), cache_.depth(), frame);
}

void BumpEnvRenderer::present(GLuint color, GLuint depth, const BumpFrame& frame) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, outputFb_.id());
    glViewport(0, 0, width_, height_);
    glBindTextureUnit(0, color);
    glBindTextureUnit(1, depth);
    glBindTextureUnit(2, environment_.id());
    const GLuint p = present_.program();
    setMat4(p, "u_inverseViewProjection", glm::mat4(glm::inverse(frame.projection * frame.view)));
    present_.draw();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

} // namespace rrc::bump_env
