// Internal: reads the scene file within the byte budget and, for GLB, checks the container
// (header, magic, version, length, chunk bounds) before tinygltf sees it: tinygltf's own GLB
// checks miss a chunk that overruns the file by less than its 8-byte header.
#pragma once
#include "load_context.hpp"

#include <cstdint>
#include <string_view>
#include <vector>

namespace rrc::scene::detail {

struct Container {
    Container() = default;
    Container(Container&&) = default;             // `json` points into `bytes`: never copy
    Container& operator=(Container&&) = default;
    Container(const Container&) = delete;
    Container& operator=(const Container&) = delete;

    std::vector<unsigned char> bytes;   // the whole file
    bool glb = false;
    std::string_view json;              // .gltf: the whole file; .glb: the JSON chunk
    size_t binSize = 0;                 // .glb: BIN chunk payload size (0 when there is none)
};

// Reads a whole file (regular files only) after checking its size against the budget.
Result<std::vector<unsigned char>> readFileBounded(const std::filesystem::path& path, LoadContext& context,
                                                   const std::string& what);

// Reads `path` and splits it: GLB when it starts with "glTF" or has the .glb extension.
Result<Container> readContainer(const std::string& path, LoadContext& context);

} // namespace rrc::scene::detail
