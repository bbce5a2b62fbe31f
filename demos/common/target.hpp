// Off-screen render targets for demos (a colour texture plus an optional depth texture in one
// framebuffer) and the reversed-Z depth state every demo renders with.
#pragma once
#include <rrc/gl_object.hpp>

#include <vector>

namespace rrc::demo {

// Defaults: one RGBA16F colour attachment and a DEPTH_COMPONENT32F depth texture.
struct RenderTargetDesc {
    int width = 0;
    int height = 0;
    std::vector<GLenum> colorFormats = {GL_RGBA16F};   // attachments 0..n-1
    GLenum depthFormat = GL_DEPTH_COMPONENT32F;        // 0: no depth attachment
    GLenum filter = GL_LINEAR;
};

class RenderTarget {
public:
    // Fails with FramebufferIncomplete (logged), also for a non-positive size.
    static Result<RenderTarget> create(const RenderTargetDesc& desc);

    void bind() const;        // binds the framebuffer and sets the viewport to its size
    GLuint framebuffer() const { return framebuffer_.id(); }
    GLuint color(size_t index = 0) const { return colors_.at(index).id(); }
    GLuint depth() const { return depth_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    Framebuffer framebuffer_;
    std::vector<Texture> colors_;
    Texture depth_;
    int width_ = 0, height_ = 0;
};

// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), glClearDepth(0), glDepthFunc(GL_GREATER): the
// state demo::perspective() is made for. Clear depth to 0 before drawing.
void enableReversedZ();

} // namespace rrc::demo
