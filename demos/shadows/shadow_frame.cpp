// ShadowRenderer's per-frame work: the shading pass of each variant (through rrc::Cache for the
// amortized one, in the control flow chosen), then the optional blur and composite.
#include "shadow_renderer.hpp"

#include "../support/gl_util.hpp"

#include <rrc/motion.hpp>

#include <algorithm>

namespace rrc::shadows {
namespace {

bool needsComposite(const ShadowSettings& s) { return s.blur || s.remap != Remap::None; }

} // namespace

const Program& ShadowRenderer::shadeProgram(Variant v, bool deferred, bool lookupPass) const {
    return shade_[v == Variant::Amortized][deferred][v == Variant::Amortized && lookupPass];
}

void ShadowRenderer::drawScene(GLuint p, const ShadowFrame& frame, const ShadowSettings& settings, bool withCache) const {
    glUseProgram(p);
    glBindTextureUnit(kShadowUnitBinding, shadowMap_.id());
    auto uniform = [&](const char* name) { return glGetUniformLocation(p, name); };
    demo::setUniform(p, "u_lightMatrix", glm::mat4(lightMatrix_));
    if (GLint l = uniform("u_taps"); l >= 0) glProgramUniform1i(p, l, std::clamp(settings.taps, 1, 256));
    if (GLint l = uniform("u_disk"); l >= 0) glProgramUniform2fv(p, l, static_cast<GLsizei>(disk_.size() / 2), disk_.data());
    if (GLint l = uniform("u_radius"); l >= 0) glProgramUniform1f(p, l, float(settings.radius / (2.0 * radius_)));
    if (GLint l = uniform("u_bias"); l >= 0) glProgramUniform1f(p, l, float(0.02 / (2.0 * radius_)));
    if (GLint l = uniform("u_frameSeed"); l >= 0) glProgramUniform2ui(p, l, frame.frame, settings.seed);
    const glm::vec3 toLight(frame.toLight);
    if (GLint l = uniform("u_toLight"); l >= 0) glProgramUniform3fv(p, l, 1, &toLight[0]);
    const GLint baseColor = uniform("u_baseColor");
    const ViewState now{frame.view, frame.projection};
    auto draw = [&](const demo::DrawCall& d) {
        const DrawMatrices m = withCache ? cache_.drawMatrices(d.model, d.prevModel) : composeDrawMatrices(now, now, d.model, d.model);
        demo::setUniform(p, "u_mvp", m.modelViewProj);
        demo::setUniform(p, "u_model", glm::mat4(d.model));
        if (baseColor >= 0) glProgramUniform4fv(p, baseColor, 1, &d.baseColor[0]);
        if (withCache) cache_.setDrawUniforms(p, m, d.objectId);
        glBindVertexArray(d.vertexArray);
        glDrawElements(GL_TRIANGLES, d.indexCount, d.indexType, nullptr);
    };
    for (const demo::DrawCall& d : scene_) draw(d);
    draw({.vertexArray = casterMesh_.vertexArray.id(), .indexCount = casterMesh_.indexCount, .model = frame.caster,
          .prevModel = frame.prevCaster, .baseColor = {0.85f, 0.35f, 0.25f, 1.0f}, .objectId = 1});
    glBindVertexArray(0);
    glUseProgram(0);
}

void ShadowRenderer::render(Variant variant, const ShadowSettings& settings, const ShadowFrame& frame) {
    updateShadowMap(frame);
    const bool deferred = needsComposite(settings);
    const bool prepass = settings.flow != Flow::SinglePass;
    if (variant == Variant::Pcf) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, pcf_.fb.id());
        glViewport(0, 0, width_, height_);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(pcf_.fb.id(), GL_COLOR, 0, zero);
        glClearNamedFramebufferfv(pcf_.fb.id(), GL_COLOR, 1, zero);
        glClearNamedFramebufferfv(pcf_.fb.id(), GL_DEPTH, 0, zero);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        if (prepass) {   // the same prepass the cached flow has: each pixel shaded once
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            drawScene(depthOnly_.id(), frame, settings, false);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDepthFunc(GL_EQUAL);
            glDepthMask(GL_FALSE);
        }
        drawScene(shadeProgram(variant, deferred, false).id(), frame, settings, false);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    } else {
        // The samples change every frame, so a frame is never "static" for the cache.
        (void)cache_.beginFrame({.view = frame.view, .projection = frame.projection, .lambda = settings.lambda,
                                 .objectsMoved = true, .depthPrepass = prepass, .skipEmptyMissPass = settings.flow == Flow::TwoPass});
        bool shadedAll = false;
        const ControlFlow flow = settings.flow == Flow::OnePass ? ControlFlow::OnePass : ControlFlow::TwoPass;
        (void)cache_.render(flow, [&](Pass pass) {
            switch (pass) {
            case Pass::DepthPrepass:
            case Pass::Probe: drawScene(depthOnly_.id(), frame, settings, true); break;
            case Pass::Shade: drawScene(shadeProgram(variant, deferred, false).id(), frame, settings, true); break;
            case Pass::Lookup:
                // Single pass: the lookup pass shades hits and misses alike, leaving the miss pass nothing.
                shadedAll = settings.flow == Flow::SinglePass;
                drawScene(shadeProgram(variant, deferred, !shadedAll).id(), frame, settings, true);
                break;
            case Pass::Miss:
                if (!shadedAll) drawScene(shadeProgram(variant, deferred, false).id(), frame, settings, true);
                break;
            case Pass::Resolve: break;
            }
        });
        cache_.endFrame();
    }
    const int v = static_cast<int>(variant);
    post_[v] = deferred;
    const GLuint visibility = variant == Variant::Pcf ? pcf_.visibility.id() : cache_.payload(0);
    lastVisibility_[v] = visibility;
    if (deferred) {
        const GLuint depth = variant == Variant::Pcf ? pcf_.depth.id() : cache_.depth();
        postProcess(variant, settings, visibility, variant == Variant::Pcf ? pcf_.color.id() : cache_.payload(1), depth);
    }
}

void ShadowRenderer::postProcess(Variant variant, const ShadowSettings& settings, GLuint visibility, GLuint albedo, GLuint depth) {
    const int v = static_cast<int>(variant);
    glViewport(0, 0, width_, height_);
    if (settings.blur) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, blurFb_.id());
        glBindTextureUnit(0, visibility);
        glBindTextureUnit(1, depth);
        const GLuint p = blur_.program();
        glProgramUniform1f(p, glGetUniformLocation(p, "u_near"), 0.1f);
        glProgramUniform1f(p, glGetUniformLocation(p, "u_depthSigma"), 0.02f);
        blur_.draw();
        // Fed back into the cache: older contributions get progressively smoother (fig. 6.9e).
        glCopyImageSubData(blurred_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, visibility, GL_TEXTURE_2D, 0, 0, 0, 0, width_, height_, 1);
        lastVisibility_[v] = visibility;
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, compositeFb_[v].id());
    glBindTextureUnit(0, visibility);
    glBindTextureUnit(1, albedo);
    glProgramUniform1i(composite_.program(), glGetUniformLocation(composite_.program(), "u_remap"), static_cast<int>(settings.remap));
    composite_.draw();
    glUseProgram(0);   // a re-init (window resize) deletes our programs: none may stay current
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

GLuint ShadowRenderer::color(Variant v) const {
    if (post_[static_cast<int>(v)]) return composited_[static_cast<int>(v)].id();
    return v == Variant::Pcf ? pcf_.color.id() : cache_.payload(1);
}

GLuint ShadowRenderer::visibility(Variant v) const { return lastVisibility_[static_cast<int>(v)]; }

demo::MeshBuffers makeCasterBox() {
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    const glm::vec3 half(0.5f, 0.8f, 0.5f), offset(0.0f, 0.8f, 0.0f);
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            const glm::vec3 u = glm::vec3(n.y, n.z, n.x), w = glm::cross(n, u);   // face axes, u x w = n
            const auto base = static_cast<uint32_t>(vertices.size() / 6);
            for (auto [a, b] : {std::pair{-1.f, -1.f}, std::pair{1.f, -1.f}, std::pair{1.f, 1.f}, std::pair{-1.f, 1.f}}) {
                const glm::vec3 p = (n + u * a + w * b) * half + offset;
                vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
            }
            indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    return demo::uploadMesh(vertices, indices);
}

} // namespace rrc::shadows
