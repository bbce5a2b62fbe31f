// KHR_debug callback and glGetError draining, both reporting through the logger.
#include <rrc/debug.hpp>

#include <atomic>
#include <string>

namespace rrc {
namespace {

std::atomic<long> glErrorCount{0}, debugErrorCount{0}, debugMessageCount{0};

void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                 const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    // Compiler diagnostics repeat the info log, which buildProgram reports with real file names.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    ++debugMessageCount;
    const bool isError = type == GL_DEBUG_TYPE_ERROR;
    if (isError) ++debugErrorCount;
    std::string text = "GL debug (id " + std::to_string(id) + "): ";
    text.append(message, length >= 0 ? static_cast<size_t>(length) : std::char_traits<char>::length(message));
    log(LogId::GlDebugMessage, isError ? LogLevel::Error : LogLevel::Warning, text);
}

} // namespace

void installDebugOutput() {
    if (!glDebugMessageCallback) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // so an error is reported at the call that caused it
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
}

std::string_view glErrorName(GLenum error) {
    switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: return "unknown GL error";
    }
}

int checkGLErrors(std::string_view where) {
    int count = 0;
    for (GLenum e = glGetError(); e != GL_NO_ERROR && count < 64; e = glGetError()) {
        ++count;
        ++glErrorCount;
        logError(LogId::GlError, std::string(glErrorName(e)) + " at " + std::string(where));
    }
    return count;
}

DebugCounters debugCounters() {
    return {glErrorCount.load(), debugErrorCount.load(), debugMessageCount.load()};
}

void resetDebugCounters() {
    glErrorCount = 0;
    debugErrorCount = 0;
    debugMessageCount = 0;
}

} // namespace rrc
