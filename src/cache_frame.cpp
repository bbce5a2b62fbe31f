// Frames and control flow: the swap that turns the last render into the cache, the cache block,
// and the passes of the one-, two- and three-pass flows with the GL state each one needs.
#include "cache_impl.hpp"

#include <cmath>
#include <string>

namespace rrc {
namespace {

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

Error noCache(const char* what) {
    return fail(LogId::CacheInvalidObject, std::string(what) + " on an empty (moved-from or default) cache");
}

} // namespace

std::string_view passName(Pass pass) {
    switch (pass) {
    case Pass::DepthPrepass: return "depth-prepass";
    case Pass::Shade: return "shade";
    case Pass::Lookup: return "lookup";
    case Pass::Probe: return "probe";
    case Pass::Miss: return "miss";
    case Pass::Resolve: return "resolve";
    }
    return "?";
}

void Cache::Impl::uploadBlock() {
    CacheBlock b{};
    b.size[0] = static_cast<float>(desc.width);
    b.size[1] = static_cast<float>(desc.height);
    b.size[2] = 1.0f / static_cast<float>(desc.width);
    b.size[3] = 1.0f / static_cast<float>(desc.height);
    b.depth[0] = static_cast<float>(cacheRange.near);
    b.depth[1] = std::isinf(cacheRange.far) ? 0.0f : static_cast<float>(cacheRange.far);
    b.depth[2] = desc.reversedZ ? 1.0f : 0.0f;
    b.depth[3] = previousValid() ? 1.0f : 0.0f;
    b.tolerance[0] = desc.depthTolerance;
    b.tolerance[1] = desc.slopeTolerance;
    b.tolerance[2] = desc.maxScale;
    b.tolerance[3] = frameDesc.lambda;
    b.frameInfo[0] = static_cast<uint32_t>(frame);
    b.frameInfo[1] = static_cast<uint32_t>(frameDesc.refresh.policy);
    b.frameInfo[2] = frameDesc.refresh.period;
    b.frameInfo[3] = frameDesc.refresh.blockSize;
    b.refreshInfo[0] = frameDesc.refresh.fraction;
    glNamedBufferSubData(block.id(), 0, sizeof(b), &b);
}

Result<void> Cache::beginFrame(const FrameDesc& f) {
    if (!impl_) return noCache("Cache::beginFrame");
    Impl& s = *impl_;
    if (!finite(f.view) || !finite(f.projection) || glm::determinant(f.view) == 0.0 || glm::determinant(f.projection) == 0.0)
        return fail(LogId::CacheNonFinite, "Cache::beginFrame: view or projection matrix is not finite or singular");
    if (!depthRangeOf(f.projection, s.desc.reversedZ))
        return fail(LogId::CacheNonFinite, std::string("Cache::beginFrame: projection is not a finite ") +
                                               (s.desc.reversedZ ? "reversed-Z" : "standard") + " perspective");
    if (!(f.lambda >= 0.0f && f.lambda < 1.0f))
        return fail(LogId::CacheBadArgument, "Cache::beginFrame: lambda must be in [0, 1), got " + std::to_string(f.lambda));
    if (f.refresh.policy == RefreshPolicy::Random && !(f.refresh.fraction >= 0.0f && f.refresh.fraction <= 1.0f))
        return fail(LogId::CacheBadArgument, "Cache::beginFrame: refresh fraction must be in [0, 1]");
    if (f.refresh.policy != RefreshPolicy::None && !s.desc.refresh)
        return fail(LogId::CacheBadArgument, "Cache::beginFrame: a refresh policy needs CacheDesc::refresh");
    if (f.refresh.blockSize == 0 || f.refresh.period == 0)
        return fail(LogId::CacheBadArgument, "Cache::beginFrame: refresh blockSize and period must be >= 1");

    const bool sameView = f.view == s.view.view && f.projection == s.view.projection;
    const bool nothingChanged = s.begun && s.cur().rendered && !s.invalidated && sameView && !f.objectsMoved &&
                                !f.forcedMisses && f.refresh.policy == RefreshPolicy::None;
    ++s.frame;
    s.frameDesc = f;
    s.staticFrame = nothingChanged;
    if (!nothingChanged) {
        // The last render becomes the cache; its view becomes the cache-time view.
        if (s.begun) {
            s.current = 1 - s.current;
            s.cacheView = s.view;
            s.cacheRange = *depthRangeOf(s.cacheView.projection, s.desc.reversedZ);
        }
        if (s.invalidated && !s.begun) s.cacheView = ViewState{f.view, f.projection};
        s.cur().rendered = false;
    }
    s.view = ViewState{f.view, f.projection};
    s.begun = true;
    s.uploadBlock();
    return {};
}

void Cache::bindForLookup() const {
    if (!impl_) { noCache("Cache::bindForLookup"); return; }
    const Impl& s = *impl_;
    const CacheTargets& p = s.prev();
    glBindTextureUnit(s.unit(kDepthUnitOffset), p.depth.id());
    if (s.desc.objectIds) glBindTextureUnit(s.unit(kIdUnitOffset), p.ids.id());
    if (s.desc.age) glBindTextureUnit(s.unit(kAgeUnitOffset), p.age.id());
    for (size_t i = 0; i < p.payloads.size(); ++i)
        glBindTextureUnit(s.unit(kPayloadUnitOffset + static_cast<int>(i)), p.payloads[i].id());
    glBindBufferBase(GL_UNIFORM_BUFFER, s.desc.uniformBinding, s.block.id());
}

void Cache::bindPayloads(int firstUnit) const {
    if (!impl_) { noCache("Cache::bindPayloads"); return; }
    for (size_t i = 0; i < impl_->cur().payloads.size(); ++i)
        glBindTextureUnit(firstUnit + static_cast<int>(i), impl_->cur().payloads[i].id());
}

void Cache::Impl::clearCurrent() {
    const GLuint fb = cur().framebuffer.id();
    GLint buffer = 0;
    for (size_t i = 0; i < desc.payloads.size(); ++i, ++buffer) {
        if (isIntegerFormat(desc.payloads[i].format)) {
            const GLuint zero[4] = {};
            glClearNamedFramebufferuiv(fb, GL_COLOR, buffer, zero);
        } else {
            glClearNamedFramebufferfv(fb, GL_COLOR, buffer, &desc.clearColor[0]);
        }
    }
    const GLuint zero[4] = {};
    for (bool present : {desc.objectIds, desc.age, desc.stats})
        if (present) glClearNamedFramebufferuiv(fb, GL_COLOR, buffer++, zero);
    const float far = desc.reversedZ ? 0.0f : 1.0f;
    if (desc.stencil) glClearNamedFramebufferfi(fb, GL_DEPTH_STENCIL, 0, far, 0);
    else glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far);
}

Result<void> Cache::Impl::markMisses(bool probe) {
    if (!markProgram) {
        auto p = internalProgram("rrc/internal/fullscreen.vert", "rrc/internal/mark_misses.frag", nullptr);
        if (!p) return p.error();
        markProgram = std::move(p).value();
    }
    // Texture unit 0 and the program are the application's: restored afterwards.
    GLint previousProgram = 0, activeTexture = 0, previousTexture = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previousTexture);
    glActiveTexture(static_cast<GLenum>(activeTexture));

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, cur().stencilOnly.id());
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glUseProgram(markProgram.id());
    glBindTextureUnit(0, cur().outcomes.id());
    glBindVertexArray(emptyVao.id());
    if (probe) glBeginQuery(GL_ANY_SAMPLES_PASSED, this->probe.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (probe) glEndQuery(GL_ANY_SAMPLES_PASSED);
    glBindVertexArray(0);
    glBindTextureUnit(0, static_cast<GLuint>(previousTexture));
    restoreProgram(previousProgram);

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, cur().framebuffer.id());
    glEnable(GL_DEPTH_TEST);
    glStencilFunc(GL_EQUAL, 2, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    return {};
}

Result<void> Cache::render(ControlFlow flow, const std::function<void(Pass)>& draw) {
    if (!impl_) return noCache("Cache::render");
    Impl& s = *impl_;
    if (!s.begun) return fail(LogId::CacheBadArgument, "Cache::render before Cache::beginFrame");
    if (!s.desc.stencil && flow != ControlFlow::OnePass && s.frameDesc.depthPrepass)
        return fail(LogId::CacheBadArgument, "Cache::render: TwoPass/ThreePass with FrameDesc::depthPrepass needs CacheDesc::stencil");
    GLint outputFramebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &outputFramebuffer);
    if (s.staticFrame) {
        // Nothing moved, nothing is refreshed or forced: the last render is this frame's render.
        if (flow == ControlFlow::ThreePass) {
            bindPayloads(s.unit(kPayloadUnitOffset));
            glViewport(0, 0, s.desc.width, s.desc.height);
            draw(Pass::Resolve);
        }
        return {};
    }
    const GLenum strict = s.desc.reversedZ ? GL_GREATER : GL_LESS;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.cur().framebuffer.id());
    glViewport(0, 0, s.desc.width, s.desc.height);
    if (s.desc.reversedZ) glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    s.clearCurrent();
    bindForLookup();
    glEnable(GL_DEPTH_TEST);

    auto pass = [&](Pass p, GLenum depthFunc, bool depthWrite, bool colorWrite) {
        glDepthFunc(depthFunc);
        glDepthMask(depthWrite ? GL_TRUE : GL_FALSE);
        const GLboolean c = colorWrite ? GL_TRUE : GL_FALSE;
        glColorMask(c, c, c, c);
        draw(p);
    };
    const bool haveCache = s.previousValid();
    // After a prepass every later pass shades only the nearest surface, once (GL_EQUAL).
    const bool prepass = flow == ControlFlow::OnePass || s.frameDesc.depthPrepass;
    // With an outcome target the lookup pass writes no stencil: a shader that discards and
    // writes stencil is depth-tested late, i.e. after running on every hidden fragment too (on
    // the temple scene that made the lookup pass cost 2.7x as much). The prepass marks covered
    // pixels instead, and markMisses() turns the outcome target into the miss pass's stencil.
    const bool markByOutcome = prepass && haveCache && flow != ControlFlow::OnePass && s.desc.stats;
    if (markByOutcome) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 1, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    }
    if (prepass) pass(Pass::DepthPrepass, strict, true, false);
    if (markByOutcome) glDisable(GL_STENCIL_TEST);
    const GLenum shadeTest = prepass ? GL_EQUAL : strict;
    if (flow == ControlFlow::OnePass) {
        pass(Pass::Shade, shadeTest, !prepass, true);
    } else if (!haveCache) {
        // Everything misses (first frame, cut, resize): no lookup, no probe, just the misses.
        pass(Pass::Miss, shadeTest, !prepass, true);
    } else {
        // How the miss pass finds its pixels (docs/cache.md, "Control flow"):
        // - prepass + outcome target: markMisses() sets stencil 2 where the lookup did not hit;
        // - prepass only: hits set stencil 1 in the lookup pass (which is then depth-tested late),
        //   the miss pass takes stencil 0;
        // - no prepass: the miss pass relies on the depth the hits wrote: a strict test passes
        //   only where the nearest surface was discarded.
        const bool skipEmpty = s.frameDesc.skipEmptyMissPass;
        if (markByOutcome) {
            pass(Pass::Lookup, shadeTest, false, true);
            if (auto r = s.markMisses(skipEmpty); !r) return r;   // also the probe
        } else {
            if (prepass) {
                glEnable(GL_STENCIL_TEST);
                glStencilFunc(GL_ALWAYS, 1, 0xff);
                glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            }
            pass(Pass::Lookup, shadeTest, !prepass, true);
            if (prepass) {
                glStencilFunc(GL_EQUAL, 0, 0xff);
                glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            }
            if (skipEmpty) {
                glBeginQuery(GL_ANY_SAMPLES_PASSED, s.probe.id());
                pass(Pass::Probe, shadeTest, false, false);
                glEndQuery(GL_ANY_SAMPLES_PASSED);
            }
        }
        if (skipEmpty) glBeginConditionalRender(s.probe.id(), GL_QUERY_WAIT);
        pass(Pass::Miss, shadeTest, !prepass, true);
        if (skipEmpty) glEndConditionalRender();
        glDisable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    }
    // Leave the depth state as GL's defaults, the output framebuffer bound.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    if (s.desc.reversedZ) glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(outputFramebuffer));
    s.cur().rendered = true;
    s.invalidated = false;
    if (flow == ControlFlow::ThreePass) {
        bindPayloads(s.unit(kPayloadUnitOffset));
        draw(Pass::Resolve);
    }
    return {};
}

void Cache::setDrawUniforms(GLuint program, const DrawMatrices& m, uint32_t objectId, bool neverCache) const {
    if (!impl_) { noCache("Cache::setDrawUniforms"); return; }
    if (const GLint l = glGetUniformLocation(program, "rrc_prevMVP"); l >= 0)
        glProgramUniformMatrix4fv(program, l, 1, GL_FALSE, &m.prevModelViewProj[0][0]);
    if (const GLint l = glGetUniformLocation(program, "rrc_objectId"); l >= 0) glProgramUniform1ui(program, l, objectId);
    if (const GLint l = glGetUniformLocation(program, "rrc_drawFlags"); l >= 0)
        glProgramUniform1ui(program, l, neverCache ? 1u : 0u);
}

DrawMatrices Cache::drawMatrices(const glm::dmat4& model, const glm::dmat4& prevModel) const {
    if (!impl_) { noCache("Cache::drawMatrices"); return {}; }
    return composeDrawMatrices(impl_->view, impl_->cacheView, model, prevModel);
}

} // namespace rrc
