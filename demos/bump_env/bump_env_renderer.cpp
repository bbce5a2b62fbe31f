#include "bump_env_renderer.hpp"

#include "../support/gl_util.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace rrc::bump_env {

const char* variantName(Variant v) { return v == Variant::Brute ? "brute" : "amortized"; }

Result<void> BumpEnvRenderer::init(int width, int height, const ShaderLibrary& library, const std::string& assetDir, bool age,
                                   bool stats) {
    width_ = width;
    height_ = height;
    // RGBA16F with rrc_storeAmortized (unbiased stochastic rounding) keeps the filter from stalling.
    // No stencil: the cached frame is one lookup pass without prepass (render() below).
    auto cache = Cache::create({.width = width, .height = height, .payloads = {{.format = GL_RGBA16F}}, .age = age,
                                .stats = stats, .stencil = false});
    if (!cache) return cache.error();
    cache_ = std::move(cache).value();
    auto defines = cache_.defines();
    defines.push_back({"AMORTIZED"});
    auto brute = buildProgram({.vertex = "bump_env/shaders/sphere.vert", .fragment = "bump_env/shaders/bump_env.frag"}, library);
    auto amortized = buildProgram({.vertex = "bump_env/shaders/sphere.vert", .fragment = "bump_env/shaders/bump_env.frag",
                                   .defines = std::move(defines)}, library);
    auto sky = demo::FullscreenPass::create(library, "bump_env/shaders/sky.frag");
    if (!brute) return brute.error();
    if (!amortized) return amortized.error();
    if (!sky) return sky.error();
    brute_ = std::move(brute).value();
    amortized_ = std::move(amortized).value();
    sky_ = std::move(sky).value();
    auto slopes = loadBumpSlopes(assetDir + "/bump.png");
    if (!slopes) return slopes.error();
    auto environment = loadCubeMap(assetDir + "/env");
    if (!environment) return environment.error();
    slopes_ = std::move(slopes).value();
    environment_ = std::move(environment).value();
    sphere_ = makeSphere(128, 64);
    bruteColor_ = demo::makeTexture2D(GL_RGBA16F, width, height, GL_NEAREST);
    bruteDepth_ = demo::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
    bruteFb_ = createFramebuffer();
    glNamedFramebufferTexture(bruteFb_.id(), GL_COLOR_ATTACHMENT0, bruteColor_.id(), 0);
    glNamedFramebufferTexture(bruteFb_.id(), GL_DEPTH_ATTACHMENT, bruteDepth_.id(), 0);
    return checkFramebuffer(bruteFb_, "bump-env brute-force target");
}

void BumpEnvRenderer::drawSphere(GLuint p, const BumpSettings& s, const BumpFrame& frame, bool withCache) const {
    glUseProgram(p);
    glBindTextureUnit(0, slopes_.id());
    glBindTextureUnit(1, environment_.id());
    const ViewState now{frame.view, frame.projection};
    const DrawMatrices m = withCache ? cache_.drawMatrices(frame.model, frame.prevModel)
                                     : composeDrawMatrices(now, now, frame.model, frame.model);
    demo::setUniform(p, "u_mvp", m.modelViewProj);
    demo::setUniform(p, "u_model", glm::mat4(frame.model));
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
    lastVariant_ = variant;
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    if (variant == Variant::Brute) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bruteFb_.id());
        glViewport(0, 0, width_, height_);
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(bruteFb_.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferfv(bruteFb_.id(), GL_DEPTH, 0, zero);
        drawSphere(brute_.id(), s, frame, false);
        drawSky(frame, 1);
    } else {
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
        // The sky goes into payload 0 only (the cache's other targets masked): behind the sphere,
        // where the depth is still clear, so it never enters a lookup (such pixels fail its depth test).
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        glEnable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, cache_.framebuffer());
        glViewport(0, 0, width_, height_);
        drawSky(frame, 8);
    }
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

GLuint BumpEnvRenderer::color() const { return lastVariant_ == Variant::Brute ? bruteColor_.id() : cache_.payload(0); }

void BumpEnvRenderer::drawSky(const BumpFrame& frame, int attachments) {
    // Only where nothing was drawn: a triangle at the (reversed-Z) far depth 0, tested for equality,
    // so the sphere's pixels are rejected by the depth test before shading.
    for (int i = 1; i < attachments; ++i) glColorMaski(GLuint(i), GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    glBindTextureUnit(2, environment_.id());
    const GLuint p = sky_.program();
    demo::setUniform(p, "u_inverseViewProjection", glm::mat4(glm::inverse(frame.projection * frame.view)));
    sky_.draw();
    glUseProgram(0);   // a re-init (window resize) deletes our programs: none may stay current
    glDepthMask(GL_TRUE);
    for (int i = 1; i < attachments; ++i) glColorMaski(GLuint(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

} // namespace rrc::bump_env
