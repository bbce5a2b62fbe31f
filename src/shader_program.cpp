// Compiling and linking composed shaders; error logs are mapped back to the original files.
#include <rrc/shader.hpp>

namespace rrc {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    if (isProgram) glGetProgramInfoLog(object, length, nullptr, log.data());
    else glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

Result<Shader> compileStage(GLenum stage, const std::string& file, const ProgramDesc& desc,
                            const ShaderLibrary& library) {
    auto composed = composeShader(file, desc.defines, library);
    if (!composed) return composed.error();
    Shader shader = createShader(stage);
    const char* text = composed.value().text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        return fail(LogId::ShaderCompileFailed,
                    "compiling " + file + " failed:\n" + mapShaderLog(infoLog(shader.id(), false), composed.value().files));
    return shader;
}

} // namespace

Result<Program> buildProgram(const ProgramDesc& desc, const ShaderLibrary& library) {
    Program program = createProgram();
    std::vector<Shader> shaders;
    const std::pair<GLenum, const std::string*> stages[] = {
        {GL_VERTEX_SHADER, &desc.vertex}, {GL_FRAGMENT_SHADER, &desc.fragment}, {GL_COMPUTE_SHADER, &desc.compute}};
    std::string names;
    for (auto [stage, file] : stages) {
        if (file->empty()) continue;
        auto shader = compileStage(stage, *file, desc, library);
        if (!shader) return shader.error();
        glAttachShader(program.id(), shader.value().id());
        shaders.push_back(std::move(shader).value());
        names += (names.empty() ? "" : " + ") + *file;
    }
    if (shaders.empty()) return fail(LogId::ProgramLinkFailed, "program has no shader stages");
    glLinkProgram(program.id());
    for (auto& s : shaders) glDetachShader(program.id(), s.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) return fail(LogId::ProgramLinkFailed, "linking " + names + " failed:\n" + infoLog(program.id(), true));
    return program;
}

} // namespace rrc
