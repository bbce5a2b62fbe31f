// A file compiled into a binary at build time (see cmake/RrcEmbed.cmake).
#pragma once
#include <span>
#include <string_view>

namespace rrc {

struct EmbeddedFile {
    std::string_view name;  // path relative to the embedding root, e.g. "rrc/lookup.frag"
    std::string_view text;
};

// The library's own GLSL snippets (shaders/rrc/*), named "rrc/<file>".
std::span<const EmbeddedFile> librarySnippets();

} // namespace rrc
