// Internal: glTF URIs. Data URIs are checked (media type tinygltf decodes, strict base64) and
// relative paths are confined to the scene's folder; tinygltf itself joins URIs unchecked and
// even falls back to the working directory, so it only reads files through fsCallbacks().
#pragma once
#include "load_context.hpp"

#include <tiny_gltf.h>

#include <string_view>

namespace rrc::scene::detail {

inline bool isDataUri(std::string_view uri) { return uri.substr(0, 5) == "data:"; }

// Checks a data: URI and returns the size of its decoded payload.
Result<uint64_t> checkDataUri(std::string_view uri, const std::string& what);

// Checks a relative-path URI (no scheme, not absolute, no '..' segment after percent-decoding the
// way tinygltf does) and returns the existing regular file it names inside context.folder.
Result<std::filesystem::path> resolveFileUri(std::string_view uri, const LoadContext& context, const std::string& what);

// File system callbacks for tinygltf that refuse anything outside context.folder and count
// every byte read against the budget. `context` must outlive the TinyGLTF object.
tinygltf::FsCallbacks fsCallbacks(LoadContext& context);

} // namespace rrc::scene::detail
