// Shader composition: GLSL files embedded at build time, `#include <rrc/...>` (library snippets)
// and `#include "relative/path"` (the caller's own files), `#define`s injected after `#version`,
// `#line` markers so compile errors name the real file and line.
#pragma once
#include <rrc/embedded.hpp>
#include <rrc/gl_object.hpp>

#include <list>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rrc {

struct Define {
    std::string name;
    std::string value = "1";
};

// A set of named GLSL files. Starts with the library's snippets ("rrc/..."); add your own.
class ShaderLibrary {
public:
    ShaderLibrary();
    ShaderLibrary(const ShaderLibrary&) = delete;  // files_ holds views into owned_
    ShaderLibrary& operator=(const ShaderLibrary&) = delete;
    ShaderLibrary(ShaderLibrary&&) = default;
    ShaderLibrary& operator=(ShaderLibrary&&) = default;
    void add(std::span<const EmbeddedFile> files);
    void add(std::string name, std::string text);
    std::optional<std::string_view> find(std::string_view name) const;

private:
    std::list<std::pair<std::string, std::string>> owned_;
    std::vector<EmbeddedFile> files_;
};

struct ComposedShader {
    std::string text;                 // what goes to glShaderSource
    std::vector<std::string> files;   // files[n] is the name of GLSL source-string number n
};

// Resolves includes (each file once; a file including itself through a chain is an error),
// injects the defines and #line markers. Fails with ShaderFileNotFound, ShaderIncludeNotFound,
// ShaderIncludeCycle or ShaderSyntax.
Result<ComposedShader> composeShader(std::string_view file, std::span<const Define> defines,
                                     const ShaderLibrary& library);

// Rewrites "N:line(col)" (Mesa) and "N(line)" (NVIDIA) prefixes of an info log to "file:line".
std::string mapShaderLog(std::string_view log, std::span<const std::string> files);

struct ProgramDesc {
    std::string vertex;    // file names in the library; empty = stage absent
    std::string fragment;
    std::string compute;
    std::vector<Define> defines;
};

// Composes, compiles and links. Errors (ShaderCompileFailed, ProgramLinkFailed, ...) name the
// original file and line.
Result<Program> buildProgram(const ProgramDesc& desc, const ShaderLibrary& library);

} // namespace rrc
