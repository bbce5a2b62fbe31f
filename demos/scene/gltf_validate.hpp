// Internal: structural validation of a parsed tinygltf::Model, which tinygltf leaves unchecked:
// every cross reference, every accessor's layout and range, enum values, node transforms, and the
// node hierarchy (one parent per node, no cycles, scene nodes are roots). Value checks that need
// the data itself (finite floats, index ranges) happen while converting.
#pragma once
#include "load_context.hpp"

#include <tiny_gltf.h>

namespace rrc::scene::detail {

Result<void> validateModel(const tinygltf::Model& model);

// The first use of each accessor ("POSITION of mesh 0 primitive 0"), for messages; "" if unused.
std::vector<std::string> accessorUses(const tinygltf::Model& model);

} // namespace rrc::scene::detail
