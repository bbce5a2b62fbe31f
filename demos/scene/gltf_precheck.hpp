// Internal: checks on the raw JSON before tinygltf parses it. They cover what tinygltf would
// trip over or silently lose: JSON errors and nesting depth, negative or non-integer indices
// (tinygltf turns -1 into "absent"), buffer and image URIs (escapes, bad base64, missing files,
// sizes), bufferView ranges (tinygltf reads images from bufferViews unchecked) and the index
// accessors tinygltf dereferences while parsing.
#pragma once
#include "gltf_container.hpp"

namespace rrc::scene::detail {

Result<void> precheckJson(const Container& container, LoadContext& context);

} // namespace rrc::scene::detail
