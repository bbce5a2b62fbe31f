#include "shadow_renderer.hpp"

#include "../support/gl_util.hpp"
#include "../support/poisson.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::shadows {
namespace {

constexpr int kMaxTaps = 256;

Result<Framebuffer> makeFramebuffer(std::initializer_list<GLuint> colors, GLuint depth, const char* what) {
    Framebuffer fb = createFramebuffer();
    std::vector<GLenum> buffers;
    for (GLuint c : colors) {
        const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(buffers.size());
        glNamedFramebufferTexture(fb.id(), attachment, c, 0);
        buffers.push_back(attachment);
    }
    if (depth) glNamedFramebufferTexture(fb.id(), GL_DEPTH_ATTACHMENT, depth, 0);
    glNamedFramebufferDrawBuffers(fb.id(), static_cast<GLsizei>(buffers.size()), buffers.empty() ? nullptr : buffers.data());
    if (buffers.empty()) glNamedFramebufferDrawBuffer(fb.id(), GL_NONE);
    if (auto r = checkFramebuffer(fb, what); !r) return r.error();
    return fb;
}

} // namespace

const char* variantName(Variant v) { return v == Variant::Pcf ? "pcf" : "amortized"; }

const char* flowName(Flow f) {
    switch (f) {
    case Flow::SinglePass: return "single-pass";
    case Flow::OnePass: return "one-pass";
    case Flow::TwoPass: return "two-pass";
    }
    return "?";
}

Result<void> ShadowRenderer::init(int width, int height, const ShaderLibrary& library, std::span<const demo::DrawCall> scene,
                                  glm::dvec3 boundsMin, glm::dvec3 boundsMax, int shadowMapSize, CacheFeatures features) {
    width_ = width;
    height_ = height;
    shadowMapSize_ = shadowMapSize;
    scene_.assign(scene.begin(), scene.end());
    center_ = 0.5 * (boundsMin + boundsMax);
    radius_ = 0.65 * glm::length(boundsMax - boundsMin) + 2.0;
    // Visibility amortizes in 32-bit float: exact stores, no rounding bias in the recursive filter.
    const GLenum visibilityFormat = features.depthInPayload ? GL_RG32F : GL_R32F;
    auto cache = Cache::create({.width = width, .height = height,
                                .payloads = {{.format = visibilityFormat, .resample = features.bilinear ? Resample::Bilinear : Resample::Nearest},
                                             {.format = GL_RGBA8, .resample = Resample::Nearest}},
                                .age = features.age, .stats = features.stats, .depthInPayload = features.depthInPayload,
                                .bilinearDepth = features.bilinear, .resampleSnap = features.resampleSnap,
                                .stencil = features.stencil});
    if (!cache) return cache.error();
    cache_ = std::move(cache).value();
    for (int amortized = 0; amortized < 2; ++amortized)
        for (int deferred = 0; deferred < 2; ++deferred)
            for (int lookup = 0; lookup <= amortized; ++lookup) {
                std::vector<Define> defines = amortized ? cache_.defines() : std::vector<Define>{};
                if (amortized) defines.push_back({"AMORTIZED"});
                if (deferred) defines.push_back({"DEFERRED"});
                if (lookup) defines.push_back({"PASS_LOOKUP"});
                auto p = buildProgram({.vertex = "shadows/shaders/scene.vert", .fragment = "shadows/shaders/shade.frag",
                                       .defines = std::move(defines)}, library);
                if (!p) return p.error();
                shade_[amortized][deferred][lookup] = std::move(p).value();
            }
    auto lightDepth = buildProgram({.vertex = "shadows/shaders/light_depth.vert", .fragment = "shadows/shaders/depth_only.frag"}, library);
    auto depthOnly = buildProgram({.vertex = "shadows/shaders/scene.vert", .fragment = "shadows/shaders/depth_only.frag"}, library);
    auto blur = demo::FullscreenPass::create(library, "shadows/shaders/blur.frag");
    auto composite = demo::FullscreenPass::create(library, "shadows/shaders/composite.frag");
    if (!lightDepth) return lightDepth.error();
    if (!depthOnly) return depthOnly.error();
    if (!blur) return blur.error();
    if (!composite) return composite.error();
    lightDepth_ = std::move(lightDepth).value();
    depthOnly_ = std::move(depthOnly).value();
    blur_ = std::move(blur).value();
    composite_ = std::move(composite).value();

    shadowMap_ = demo::makeTexture2D(GL_DEPTH_COMPONENT32F, shadowMapSize, shadowMapSize, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTextureParameteri(shadowMap_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(shadowMap_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(shadowMap_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTextureParameteri(shadowMap_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float far[4] = {1, 1, 1, 1};   // outside the light's frustum: lit
    glTextureParameterfv(shadowMap_.id(), GL_TEXTURE_BORDER_COLOR, far);
    auto shadowFb = makeFramebuffer({}, shadowMap_.id(), "shadow map");
    staticDepth_ = demo::makeTexture2D(GL_DEPTH_COMPONENT32F, shadowMapSize, shadowMapSize, GL_NEAREST, GL_CLAMP_TO_EDGE);
    auto staticFb = makeFramebuffer({}, staticDepth_.id(), "static shadow depth");
    if (!staticFb) return staticFb.error();
    staticFb_ = std::move(staticFb).value();
    pcf_.visibility = demo::makeTexture2D(GL_R32F, width, height, GL_NEAREST, GL_CLAMP_TO_EDGE);
    pcf_.color = demo::makeTexture2D(GL_RGBA8, width, height, GL_NEAREST, GL_CLAMP_TO_EDGE);
    pcf_.depth = demo::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST, GL_CLAMP_TO_EDGE);
    auto pcfFb = makeFramebuffer({pcf_.visibility.id(), pcf_.color.id()}, pcf_.depth.id(), "PCF target");
    // The blur's result is copied back into the cache's visibility payload: the same format.
    blurred_ = demo::makeTexture2D(visibilityFormat, width, height, GL_NEAREST, GL_CLAMP_TO_EDGE);
    auto blurFb = makeFramebuffer({blurred_.id()}, 0, "blur target");
    if (!shadowFb) return shadowFb.error();
    if (!pcfFb) return pcfFb.error();
    if (!blurFb) return blurFb.error();
    shadowFb_ = std::move(shadowFb).value();
    pcf_.fb = std::move(pcfFb).value();
    blurFb_ = std::move(blurFb).value();
    for (int v = 0; v < 2; ++v) {
        composited_[v] = demo::makeTexture2D(GL_RGBA8, width, height, GL_NEAREST, GL_CLAMP_TO_EDGE);
        auto fb = makeFramebuffer({composited_[v].id()}, 0, "composite target");
        if (!fb) return fb.error();
        compositeFb_[v] = std::move(fb).value();
    }
    casterMesh_ = makeCasterBox();
    disk_.clear();
    for (glm::vec2 t : demo::poissonDisk(kMaxTaps, 7)) disk_.insert(disk_.end(), {t.x, t.y});
    shadowMapValid_ = staticValid_ = false;
    shadowMapRenders_ = staticRenders_ = 0;
    return {};
}

void ShadowRenderer::drawDepth(const glm::dmat4& model, GLuint vertexArray, GLsizei count, GLenum type) const {
    demo::setUniform(lightDepth_.id(), "u_mvp", glm::mat4(lightProjection_ * lightView_ * model));
    glBindVertexArray(vertexArray);
    glDrawElements(GL_TRIANGLES, count, type, nullptr);
}

void ShadowRenderer::updateShadowMap(const ShadowFrame& frame) {
    // Skip what is not needed: the static scene's depth is rendered only when the light turns;
    // when only the caster moved, the map is that depth plus the caster (a copy and 12 triangles
    // instead of the whole temple); when nothing that casts moved, the map stays.
    const bool lightMoved = !staticValid_ || frame.toLight != lastToLight_;
    if (!lightMoved && shadowMapValid_ && frame.caster == lastCaster_) return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    glViewport(0, 0, shadowMapSize_, shadowMapSize_);
    glUseProgram(lightDepth_.id());
    if (lightMoved) {
        const glm::dvec3 up = std::abs(frame.toLight.y) > 0.99 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        lightView_ = glm::lookAt(center_ + frame.toLight * (2.0 * radius_), center_, up);
        lightProjection_ = glm::ortho(-radius_, radius_, -radius_, radius_, radius_, 3.0 * radius_);
        const glm::dmat4 toUnit = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) * glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
        lightMatrix_ = toUnit * lightProjection_ * lightView_;
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, staticFb_.id());
        const float one = 1.0f;
        glClearNamedFramebufferfv(staticFb_.id(), GL_DEPTH, 0, &one);
        for (const demo::DrawCall& d : scene_) drawDepth(d.model, d.vertexArray, d.indexCount, d.indexType);
        staticValid_ = true;
        ++staticRenders_;
    }
    glCopyImageSubData(staticDepth_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, shadowMap_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       shadowMapSize_, shadowMapSize_, 1);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, shadowFb_.id());
    drawDepth(frame.caster, casterMesh_.vertexArray.id(), casterMesh_.indexCount, GL_UNSIGNED_INT);
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    lastToLight_ = frame.toLight;
    lastCaster_ = frame.caster;
    shadowMapValid_ = true;
    ++shadowMapRenders_;
}

} // namespace rrc::shadows
