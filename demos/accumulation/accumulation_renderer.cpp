#include "accumulation_renderer.hpp"

#include "support/gl_util.hpp"
#include "support/timing.hpp"

namespace rrc::accumulation {

const char* variantName(Variant v) { return v == Variant::Brute ? "brute" : "cached"; }

Result<void> AccumulationRenderer::init(int width, int height, ShaderLibrary& library, const RendererSettings& settings) {
    width_ = width;
    height_ = height;
    settings_ = settings;
    // RGBA8 payload: the colour before accumulation is 8-bit in both variants (brute's target too).
    auto cache = Cache::create({.width = width, .height = height,
                                .payloads = {{.format = GL_RGBA8, .resample = settings_.resample}},
                                .stats = settings_.stats, .stencil = settings_.flow != ControlFlow::OnePass,
                                .refresh = settings_.refreshPeriod > 0, .clearColor = settings.background});
    if (!cache) return cache.error();
    cache_ = std::move(cache).value();
    for (bool skinned : {false, true}) {
        std::vector<Define> base = cache_.defines();
        base.push_back({"DEMO_OCTAVES", std::to_string(settings_.octaves)});
        if (skinned) base.push_back({"SKINNED"});
        auto build = [&](const char* fragment, const char* pass) -> Result<Program> {
            auto defines = base;
            if (pass) defines.push_back({pass});
            return buildProgram({.vertex = "accumulation/shaders/scene.vert", .fragment = fragment, .defines = defines}, library);
        };
        Result<Program> built[] = {build("accumulation/shaders/depth.frag", nullptr),
                                   build("accumulation/shaders/shade.frag", "PASS_LOOKUP"),
                                   build("accumulation/shaders/shade.frag", "PASS_MISS"),
                                   build("accumulation/shaders/shade.frag", nullptr),
                                   build("accumulation/shaders/shade.frag", "BRUTE")};
        for (auto& b : built)
            if (!b) return b.error();
        (skinned ? skinned_ : static_) = {std::move(built[0]).value(), std::move(built[1]).value(), std::move(built[2]).value(),
                                          std::move(built[3]).value(), std::move(built[4]).value()};
    }
    bruteColor_ = demo::makeTexture2D(GL_RGBA8, width, height);
    bruteDepth_ = demo::makeTexture2D(GL_DEPTH_COMPONENT32F, width, height);
    bruteFb_ = createFramebuffer();
    glNamedFramebufferTexture(bruteFb_.id(), GL_COLOR_ATTACHMENT0, bruteColor_.id(), 0);
    glNamedFramebufferTexture(bruteFb_.id(), GL_DEPTH_ATTACHMENT, bruteDepth_.id(), 0);
    if (auto r = checkFramebuffer(bruteFb_, "accumulation brute-force target"); !r) return r;
    permutation_ = demo::permutationTexture(1);
    return accumulator_.init(width, height, library);
}

const Program& AccumulationRenderer::program(const Programs& set, Variant variant, Pass pass) const {
    switch (pass) {
    case Pass::Lookup: return set.lookup;
    case Pass::Miss: return set.miss;
    case Pass::Shade: return variant == Variant::Brute ? set.brute : set.shade;
    default: return set.depth;
    }
}

void AccumulationRenderer::drawScene(Variant variant, Pass pass, const SampleView& sample, const SceneRef& scene) const {
    const Cache* cache = variant == Variant::Cached ? &cache_ : nullptr;
    const ViewState now{sample.view, sample.projection};
    glBindTextureUnit(5, permutation_.id());
    auto matrices = [&](const glm::dmat4& model, const glm::dmat4& prevModel) {
        return cache ? cache->drawMatrices(model, prevModel) : composeDrawMatrices(now, now, model, model);
    };
    const GLuint ps = program(static_, variant, pass).id();
    glUseProgram(ps);
    demo::setUniform(ps, "u_patternScale", settings_.staticPatternScale);
    const GLint baseColor = glGetUniformLocation(ps, "u_baseColor");
    for (const demo::DrawCall& d : scene.statics) {
        const DrawMatrices m = matrices(d.model, d.prevModel);
        demo::setUniform(ps, "u_mvp", m.modelViewProj);
        demo::setUniform(ps, "u_model", glm::mat4(d.model));
        if (baseColor >= 0) glProgramUniform4fv(ps, baseColor, 1, &d.baseColor[0]);
        if (cache) cache->setDrawUniforms(ps, m, d.objectId);
        glBindVertexArray(d.vertexArray);
        glDrawElements(GL_TRIANGLES, d.indexCount, d.indexType, nullptr);
    }
    if (scene.character) {
        const GLuint pk = program(skinned_, variant, pass).id();
        glUseProgram(pk);
        demo::setUniform(pk, "u_patternScale", settings_.characterPatternScale);
        const GLint color = glGetUniformLocation(pk, "u_baseColor");
        scene.character->forEachDraw([&](const scene::DrawItem& item) {
            const DrawMatrices m = matrices(item.world, item.previousWorld);
            demo::setUniform(pk, "u_mvp", m.modelViewProj);
            demo::setUniform(pk, "u_model", glm::mat4(item.world));
            const glm::vec4 c = item.material ? item.material->baseColorFactor : glm::vec4(1.0f);
            if (color >= 0) glProgramUniform4fv(pk, color, 1, &c[0]);
            if (cache) cache->setDrawUniforms(pk, m, 0, scene.characterNeverCached);
            item.draw();
        });
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

void AccumulationRenderer::renderBrute(const SampleView& sample, const SceneRef& scene) {
    // Brute force at its best: a depth prepass, then the expensive shader once per pixel.
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bruteFb_.id());
    glViewport(0, 0, width_, height_);
    const float zero = 0.0f;
    glClearNamedFramebufferfv(bruteFb_.id(), GL_COLOR, 0, &settings_.background[0]);
    glClearNamedFramebufferfv(bruteFb_.id(), GL_DEPTH, 0, &zero);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    drawScene(Variant::Brute, Pass::DepthPrepass, sample, scene);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    drawScene(Variant::Brute, Pass::Shade, sample, scene);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

void AccumulationRenderer::renderCached(const SampleView& sample, const SceneRef& scene, bool first) {
    if (first) cache_.invalidate();   // the first sample of every output frame is shaded in full
    RefreshDesc refresh{};
    if (settings_.refreshPeriod > 0) refresh = {.policy = RefreshPolicy::RoundRobin, .period = settings_.refreshPeriod, .blockSize = 8};
    (void)cache_.beginFrame({.view = sample.view, .projection = sample.projection, .refresh = refresh,
                             .forcedMisses = scene.characterNeverCached && scene.character,
                             .objectsMoved = scene.moving, .skipEmptyMissPass = settings_.probe});
    (void)cache_.render(settings_.flow, [&](Pass pass) { drawScene(Variant::Cached, pass, sample, scene); });
    cache_.endFrame();
}

void AccumulationRenderer::render(Variant variant, const SceneRef& scene, int samples, const SampleFn& sampleAt, bool trackHits) {
    hits_ = hitTotal_ = 0;
    accumulator_.clear();
    const float weight = 1.0f / float(samples);
    for (int i = 0; i < samples; ++i) {
        const SampleView sample = sampleAt(i, samples);
        if (variant == Variant::Brute) {
            renderBrute(sample, scene);
        } else {
            renderCached(sample, scene, i == 0);
            if (trackHits && settings_.stats && i > 0) {
                const Stats s = cache_.finishStats();
                hits_ += double(s.hits);
                hitTotal_ += double(s.hits + s.misses + s.forced + s.refreshed);
            }
        }
        accumulator_.add(lastSample(variant), weight);
    }
}

} // namespace rrc::accumulation
