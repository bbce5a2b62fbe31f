// Loading the GL entry points, GL object helpers and framebuffer status names.
#include <rrc/gl_object.hpp>

#include <string>

namespace rrc {

Result<void> loadGL(GLADloadfunc getProcAddress) {
    const int version = gladLoadGL(getProcAddress);
    if (version == 0) return fail(LogId::GlLoadFailed, "gladLoadGL failed: no GL context current?");
    const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major * 10 + minor < 45)
        return fail(LogId::GlLoadFailed, "GL 4.5 core required, context offers " +
                                             std::to_string(major) + "." + std::to_string(minor));
    return {};
}

Texture createTexture(GLenum target) { GLuint id = 0; glCreateTextures(target, 1, &id); return Texture(id); }
Framebuffer createFramebuffer() { GLuint id = 0; glCreateFramebuffers(1, &id); return Framebuffer(id); }
Renderbuffer createRenderbuffer() { GLuint id = 0; glCreateRenderbuffers(1, &id); return Renderbuffer(id); }
Buffer createBuffer() { GLuint id = 0; glCreateBuffers(1, &id); return Buffer(id); }
VertexArray createVertexArray() { GLuint id = 0; glCreateVertexArrays(1, &id); return VertexArray(id); }
Shader createShader(GLenum stage) { return Shader(glCreateShader(stage)); }
Program createProgram() { return Program(glCreateProgram()); }
Query createQuery(GLenum target) { GLuint id = 0; glCreateQueries(target, 1, &id); return Query(id); }

long liveGlObjects() {
    return Texture::liveCount() + Framebuffer::liveCount() + Renderbuffer::liveCount() +
           Buffer::liveCount() + VertexArray::liveCount() + Shader::liveCount() +
           Program::liveCount() + Query::liveCount();
}

std::string_view framebufferStatusName(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: return "unknown framebuffer status";
    }
}

Result<void> checkFramebuffer(const Framebuffer& framebuffer, std::string_view label) {
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer.id(), GL_DRAW_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return {};
    return fail(LogId::FramebufferIncomplete,
                std::string(label) + ": framebuffer incomplete: " + std::string(framebufferStatusName(status)));
}

} // namespace rrc
