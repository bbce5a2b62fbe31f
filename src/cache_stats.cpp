// Outcome statistics without stalls (a ring of count buffers read once their fence has
// signalled) and the hit/miss visualisation.
#include "cache_impl.hpp"

namespace rrc {

Result<Program> internalProgram(const char* vertex, const char* fragment, const char* compute) {
    ShaderLibrary library;
    return buildProgram({.vertex = vertex ? vertex : "", .fragment = fragment ? fragment : "",
                         .compute = compute ? compute : ""}, library);
}

namespace {

void accumulate(Stats& s, const uint32_t counts[8]) {
    for (int i = 0; i < 8; ++i) s.counts[i] = counts[i];
    const auto c = [&](Outcome o) { return s.counts[static_cast<int>(o)]; };
    s.hits = c(Outcome::Hit);
    s.misses = c(Outcome::Offscreen) + c(Outcome::Disoccluded) + c(Outcome::IdMismatch) + c(Outcome::Invalid);
    s.forced = c(Outcome::Forced);
    s.refreshed = c(Outcome::Refreshed);
    s.valid = true;
}

} // namespace

void Cache::Impl::collectStats(bool wait) {
    // Oldest first, so `latest` ends up at the newest finished frame.
    for (int k = 0; k < static_cast<int>(slots.size()); ++k) {
        StatsSlot& slot = slots[(nextSlot + k) % slots.size()];
        if (!slot.fence) continue;
        const GLenum state = glClientWaitSync(slot.fence, wait ? GL_SYNC_FLUSH_COMMANDS_BIT : 0,
                                              wait ? GLuint64(10'000'000'000) : 0);
        if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) continue;
        uint32_t counts[8] = {};
        glGetNamedBufferSubData(slot.counts.id(), 0, sizeof(counts), counts);
        glDeleteSync(slot.fence);
        slot.fence = nullptr;
        if (slot.frame >= latest.frame || !latest.valid) {
            latest = Stats{};
            latest.frame = slot.frame;
            accumulate(latest, counts);
        }
    }
}

void Cache::endFrame() {
    if (!impl_) { logError(LogId::CacheInvalidObject, "Cache::endFrame on an empty (moved-from or default) cache"); return; }
    Impl& s = *impl_;
    if (!s.desc.stats || s.staticFrame || !s.cur().rendered) return;
    if (!s.statsProgram) {
        auto p = internalProgram(nullptr, nullptr, "rrc/internal/stats.comp");
        if (!p) return;
        s.statsProgram = std::move(p).value();
    }
    StatsSlot& slot = s.slots[s.nextSlot];
    if (slot.fence) s.collectStats(true);  // ring full: the oldest frame must be done by now
    s.nextSlot = (s.nextSlot + 1) % static_cast<int>(s.slots.size());
    const uint32_t zero = 0;
    glClearNamedBufferData(slot.counts.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    // The count pass uses texture unit 0 and storage buffer binding 0: the application's
    // bindings there (and the program) are restored afterwards.
    GLint previousProgram = 0, activeTexture = 0, previousTexture = 0, previousStorage = 0, previousIndexed = 0;
    GLint64 previousStart = 0, previousSize = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previousTexture);
    glActiveTexture(static_cast<GLenum>(activeTexture));
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &previousStorage);
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &previousIndexed);
    glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, 0, &previousStart);
    glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, 0, &previousSize);
    glUseProgram(s.statsProgram.id());
    glBindTextureUnit(0, s.cur().outcomes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, slot.counts.id());
    // 8x8 invocations per group, 4x4 pixels per invocation.
    glDispatchCompute(static_cast<GLuint>((s.desc.width + 31) / 32), static_cast<GLuint>((s.desc.height + 31) / 32), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    restoreProgram(previousProgram);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previousTexture));
    glActiveTexture(static_cast<GLenum>(activeTexture));
    if (previousSize > 0)
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLuint>(previousIndexed), static_cast<GLintptr>(previousStart),
                          static_cast<GLsizeiptr>(previousSize));
    else
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLuint>(previousIndexed));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(previousStorage));
    slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    slot.frame = s.frame;
    s.collectStats(false);
}

Stats Cache::stats() const {
    if (!impl_) return {};
    impl_->collectStats(false);
    return impl_->latest;
}

Stats Cache::finishStats() {
    if (!impl_) return {};
    impl_->collectStats(true);
    return impl_->latest;
}

void Cache::visualize(Texture& target) const {
    if (!impl_) { logError(LogId::CacheInvalidObject, "Cache::visualize on an empty (moved-from or default) cache"); return; }
    Impl& s = *impl_;
    if (!s.desc.stats) { logError(LogId::CacheBadArgument, "Cache::visualize needs CacheDesc::stats"); return; }
    if (!s.visualizeProgram) {
        auto p = internalProgram("rrc/internal/fullscreen.vert", "rrc/internal/visualize.frag", nullptr);
        if (!p) return;
        s.visualizeProgram = std::move(p).value();
    }
    GLint w = 0, h = 0;
    if (target) {
        glGetTextureLevelParameteriv(target.id(), 0, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(target.id(), 0, GL_TEXTURE_HEIGHT, &h);
    }
    if (!target || w != s.desc.width || h != s.desc.height) {
        target = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(target.id(), 1, GL_RGBA8, s.desc.width, s.desc.height);
    }
    Framebuffer fb = createFramebuffer();
    glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    GLint previousFramebuffer = 0, previousProgram = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb.id());
    glViewport(0, 0, s.desc.width, s.desc.height);
    glUseProgram(s.visualizeProgram.id());
    glBindTextureUnit(0, s.cur().outcomes.id());
    glBindVertexArray(s.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    restoreProgram(previousProgram);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
}

} // namespace rrc
