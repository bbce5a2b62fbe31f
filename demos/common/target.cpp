// Render target creation with direct state access (GL 4.5), and the reversed-Z state.
// Completeness is checked once here, so demos never render into a broken framebuffer.
#include "target.hpp"

#include <string>

namespace rrc::demo {

Result<RenderTarget> RenderTarget::create(const RenderTargetDesc& desc) {
    if (desc.width <= 0 || desc.height <= 0)
        return fail(LogId::FramebufferIncomplete, "render target size must be positive, got " +
                                                 std::to_string(desc.width) + "x" + std::to_string(desc.height));
    RenderTarget t;
    t.width_ = desc.width;
    t.height_ = desc.height;
    t.framebuffer_ = createFramebuffer();
    std::vector<GLenum> drawBuffers;
    for (GLenum format : desc.colorFormats) {
        Texture tex = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(tex.id(), 1, format, desc.width, desc.height);
        glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(desc.filter));
        glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(desc.filter));
        glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        const auto attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + drawBuffers.size());
        glNamedFramebufferTexture(t.framebuffer_.id(), attachment, tex.id(), 0);
        drawBuffers.push_back(attachment);
        t.colors_.push_back(std::move(tex));
    }
    glNamedFramebufferDrawBuffers(t.framebuffer_.id(), static_cast<GLsizei>(drawBuffers.size()),
                                  drawBuffers.empty() ? nullptr : drawBuffers.data());
    if (drawBuffers.empty()) glNamedFramebufferDrawBuffer(t.framebuffer_.id(), GL_NONE);
    if (desc.depthFormat != 0) {
        t.depth_ = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(t.depth_.id(), 1, desc.depthFormat, desc.width, desc.height);
        glTextureParameteri(t.depth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t.depth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glNamedFramebufferTexture(t.framebuffer_.id(), GL_DEPTH_ATTACHMENT, t.depth_.id(), 0);
    }
    if (auto ok = checkFramebuffer(t.framebuffer_, "demo render target"); !ok) return ok.error();
    return t;
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width_, height_);
}

void enableReversedZ() {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glClearDepth(0.0);
    glDepthFunc(GL_GREATER);
}

} // namespace rrc::demo
