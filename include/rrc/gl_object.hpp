// Move-only owners of GL object names (textures, framebuffers, ...): the destructor deletes the
// name, release() hands it over, a GLuint constructor adopts one. Live counts per kind let tests
// prove that nothing leaks.
#pragma once
#include <rrc/gl.hpp>

#include <atomic>
#include <string_view>
#include <utility>

namespace rrc {

template <class Traits>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint id) noexcept : id_(id) { if (id_) ++Traits::live; }
    ~GlObject() { reset(); }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) { reset(); id_ = std::exchange(other.id_, 0); }
        return *this;
    }

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    // Gives up ownership without deleting the name.
    GLuint release() { if (id_) --Traits::live; return std::exchange(id_, 0); }
    void reset() {
        if (id_) { Traits::destroy(id_); --Traits::live; id_ = 0; }
    }
    // Objects of this kind currently owned by some GlObject in the process.
    static long liveCount() { return Traits::live; }

private:
    GLuint id_ = 0;
};

#define RRC_GL_TRAITS(Name, destroyCall)                                                  \
    struct Name##Traits {                                                                \
        static inline std::atomic<long> live{0};                                         \
        static void destroy(GLuint id) { destroyCall; }                                  \
    };                                                                                   \
    using Name = GlObject<Name##Traits>;

RRC_GL_TRAITS(Texture, glDeleteTextures(1, &id))
RRC_GL_TRAITS(Framebuffer, glDeleteFramebuffers(1, &id))
RRC_GL_TRAITS(Renderbuffer, glDeleteRenderbuffers(1, &id))
RRC_GL_TRAITS(Buffer, glDeleteBuffers(1, &id))
RRC_GL_TRAITS(VertexArray, glDeleteVertexArrays(1, &id))
RRC_GL_TRAITS(Shader, glDeleteShader(id))
RRC_GL_TRAITS(Program, glDeleteProgram(id))
RRC_GL_TRAITS(Query, glDeleteQueries(1, &id))
#undef RRC_GL_TRAITS

Texture createTexture(GLenum target);
Framebuffer createFramebuffer();
Renderbuffer createRenderbuffer();
Buffer createBuffer();
VertexArray createVertexArray();
Shader createShader(GLenum stage);
Program createProgram();
Query createQuery(GLenum target);

// Sum of liveCount() over every kind above.
long liveGlObjects();

// "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT" etc.; "GL_FRAMEBUFFER_COMPLETE" for complete.
std::string_view framebufferStatusName(GLenum status);
// Checks a framebuffer's completeness; on failure logs FramebufferIncomplete naming `label`.
Result<void> checkFramebuffer(const Framebuffer& framebuffer, std::string_view label);

} // namespace rrc
