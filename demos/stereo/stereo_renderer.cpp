#include "stereo_renderer.hpp"

#include "../support/gl_util.hpp"
#include "../support/timing.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::stereo {

const char* variantName(Variant v) {
    switch (v) {
    case Variant::Brute: return "brute";
    case Variant::Cached: return "cached";
    case Variant::CachedViewDependent: return "cached-view-dependent";
    }
    return "?";
}

EyeViews eyeViews(const glm::dmat4& centerView, const glm::dmat4& projection, double separation) {
    // Shifting the eye by +d along camera x moves the world by -d in view space.
    auto shifted = [&](double d) { return glm::translate(glm::dmat4(1.0), glm::dvec3(-d, 0, 0)) * centerView; };
    const glm::dmat4 inv = glm::inverse(centerView);
    const glm::dvec3 center(inv[3]), right(inv[0]);
    return {shifted(-separation / 2), shifted(separation / 2), center - right * (separation / 2),
            center + right * (separation / 2), projection};
}

Result<void> StereoRenderer::init(int width, int height, ShaderLibrary& library, int octaves) {
    width_ = width;
    height_ = height;
    const bool stencil = flow_ != ControlFlow::OnePass;   // only the two-pass flow's prepass needs it
    auto cache = Cache::create({.width = width, .height = height, .payloads = {{.format = GL_RGBA8}}, .stencil = stencil});
    auto cacheVD = Cache::create({.width = width, .height = height,
                                  .payloads = {{.format = GL_RGBA8}, {.format = GL_RGBA16F}}, .stencil = stencil});
    if (!cache) return cache.error();
    if (!cacheVD) return cacheVD.error();
    cache_ = std::move(cache).value();
    cacheVD_ = std::move(cacheVD).value();
    const Define octaveDefine{"DEMO_OCTAVES", std::to_string(octaves)};
    auto build = [&](const char* fragment, std::vector<Define> defines) -> Result<Program> {
        defines.push_back(octaveDefine);
        return buildProgram({.vertex = "stereo/shaders/scene.vert", .fragment = fragment, .defines = std::move(defines)}, library);
    };
    auto programsFor = [&](const Cache& c, bool viewDependent, Programs& out) -> Result<void> {
        auto defines = c.defines();
        if (viewDependent) defines.push_back({"VIEW_DEPENDENT"});
        auto with = [&](const char* d) { auto x = defines; x.push_back({d}); return x; };
        auto lookup = build("stereo/shaders/stereo.frag", with("PASS_LOOKUP"));
        auto miss = build("stereo/shaders/stereo.frag", with("PASS_MISS"));
        auto shade = build("stereo/shaders/stereo.frag", defines);
        auto depth = build("stereo/shaders/depth.frag", defines);
        if (!lookup) return lookup.error();
        if (!miss) return miss.error();
        if (!shade) return shade.error();
        if (!depth) return depth.error();
        out = {std::move(lookup).value(), std::move(miss).value(), std::move(shade).value(), std::move(depth).value()};
        return {};
    };
    if (auto r = programsFor(cache_, false, cached_); !r) return r;
    if (auto r = programsFor(cacheVD_, true, cachedVD_); !r) return r;
    auto brute = build("stereo/shaders/stereo.frag", {{"BRUTE"}});
    if (!brute) return brute.error();
    brute_ = std::move(brute).value();
    auto composite = buildProgram({.vertex = "stereo/shaders/fullscreen.vert", .fragment = "stereo/shaders/anaglyph.frag"}, library);
    if (!composite) return composite.error();
    composite_ = std::move(composite).value();

    bruteLeft_ = demo::makeTexture2D(GL_RGBA8, width, height);
    bruteRight_ = demo::makeTexture2D(GL_RGBA8, width, height);
    bruteSpecular_ = demo::makeTexture2D(GL_R8, width, height);
    bruteDepth_ = demo::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height);
    anaglyph_ = demo::makeTexture2D(GL_RGBA8, width, height);
    for (auto [fb, color] : {std::pair{&bruteLeftFb_, &bruteLeft_}, std::pair{&bruteRightFb_, &bruteRight_}}) {
        *fb = createFramebuffer();
        glNamedFramebufferTexture(fb->id(), GL_COLOR_ATTACHMENT0, color->id(), 0);
        glNamedFramebufferTexture(fb->id(), GL_COLOR_ATTACHMENT1, bruteSpecular_.id(), 0);
        glNamedFramebufferTexture(fb->id(), GL_DEPTH_ATTACHMENT, bruteDepth_.id(), 0);
        const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fb->id(), 2, buffers);
        if (auto r = checkFramebuffer(*fb, "stereo brute-force target"); !r) return r;
    }
    anaglyphFb_ = createFramebuffer();
    glNamedFramebufferTexture(anaglyphFb_.id(), GL_COLOR_ATTACHMENT0, anaglyph_.id(), 0);
    if (auto r = checkFramebuffer(anaglyphFb_, "anaglyph target"); !r) return r;
    emptyVao_ = createVertexArray();
    permutation_ = demo::permutationTexture(1);
    return {};
}

void StereoRenderer::drawScene(const Program& program, const glm::dmat4& view, const glm::dmat4& projection, glm::dvec3 eye,
                               const Cache* cache, std::span<const demo::DrawCall> scene) const {
    const GLuint p = program.id();
    glUseProgram(p);
    glBindTextureUnit(5, permutation_.id());
    if (GLint l = glGetUniformLocation(p, "u_eye"); l >= 0) glProgramUniform3f(p, l, float(eye.x), float(eye.y), float(eye.z));
    const GLint baseColor = glGetUniformLocation(p, "u_baseColor");
    const ViewState now{view, projection};
    for (const demo::DrawCall& d : scene) {
        const DrawMatrices m = cache ? cache->drawMatrices(d.model, d.prevModel) : composeDrawMatrices(now, now, d.model, d.model);
        demo::setUniform(p, "u_mvp", m.modelViewProj);
        demo::setUniform(p, "u_model", glm::mat4(d.model));
        if (baseColor >= 0) glProgramUniform4fv(p, baseColor, 1, &d.baseColor[0]);
        if (cache) cache->setDrawUniforms(p, m, d.objectId);
        glBindVertexArray(d.vertexArray);
        glDrawElements(GL_TRIANGLES, d.indexCount, d.indexType, nullptr);
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

void StereoRenderer::composite(GLuint left, GLuint right) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, anaglyphFb_.id());
    glViewport(0, 0, width_, height_);
    glUseProgram(composite_.id());
    glBindTextureUnit(0, left);
    glBindTextureUnit(1, right);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void StereoRenderer::render(Variant variant, const EyeViews& eyes, std::span<const demo::DrawCall> scene) {
    if (variant == Variant::Brute) {
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        for (auto [fb, view, eye] : {std::tuple{&bruteRightFb_, eyes.right, eyes.rightEye}, std::tuple{&bruteLeftFb_, eyes.left, eyes.leftEye}}) {
            const float zero = 0.0f, black[4] = {0, 0, 0, 1};
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb->id());
            glViewport(0, 0, width_, height_);
            glClearNamedFramebufferfv(fb->id(), GL_COLOR, 0, black);
            glClearNamedFramebufferfv(fb->id(), GL_COLOR, 1, black);
            glClearNamedFramebufferfv(fb->id(), GL_DEPTH, 0, &zero);
            // A depth prepass, so the expensive shader runs once per pixel: brute force at its best.
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glDepthFunc(GL_GREATER);
            drawScene(cached_.depthOnly, view, eyes.projection, eye, nullptr, scene);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDepthFunc(GL_EQUAL);
            glDepthMask(GL_FALSE);
            drawScene(brute_, view, eyes.projection, eye, nullptr, scene);
            glDepthMask(GL_TRUE);
        }
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        composite(bruteLeft_.id(), bruteRight_.id());
        return;
    }
    Cache& cache = this->cache(variant);
    cache.invalidate();   // the right eye is always rendered in full
    renderEye(variant, eyes.right, eyes.projection, eyes.rightEye, scene);
    renderEye(variant, eyes.left, eyes.projection, eyes.leftEye, scene);
    composite(cache.payload(0), cache.previousPayload(0));
}

void StereoRenderer::renderEye(Variant variant, const glm::dmat4& view, const glm::dmat4& projection, glm::dvec3 position,
                               std::span<const demo::DrawCall> scene) {
    Cache& cache = this->cache(variant);
    const Programs& programs = variant == Variant::CachedViewDependent ? cachedVD_ : cached_;
    (void)cache.beginFrame({.view = view, .projection = projection, .forcedMisses = variant == Variant::CachedViewDependent,
                            .skipEmptyMissPass = probe_});
    (void)cache.render(flow_, [&](Pass pass) {
        const Program& program = pass == Pass::Lookup ? programs.lookup
                               : pass == Pass::Miss   ? programs.miss
                               : pass == Pass::Shade  ? programs.shade : programs.depthOnly;
        drawScene(program, view, projection, position, &cache, scene);
    });
    cache.endFrame();
}

void StereoRenderer::renderLeftAgain(Variant variant, const EyeViews& eyes, std::span<const demo::DrawCall> scene) {
    renderEye(variant, eyes.left, eyes.projection, eyes.leftEye, scene);
}

GLuint StereoRenderer::leftEye(Variant v) const {
    return v == Variant::Brute ? bruteLeft_.id() : (v == Variant::Cached ? cache_.payload(0) : cacheVD_.payload(0));
}

GLuint StereoRenderer::rightEye(Variant v) const {
    return v == Variant::Brute ? bruteRight_.id() : (v == Variant::Cached ? cache_.previousPayload(0) : cacheVD_.previousPayload(0));
}

} // namespace rrc::stereo
