// A scene ready to draw for the demos and rrc-bench: a glTF file through rrc_scene (loaded,
// validated, uploaded, posed once) or the procedural colonnade, flattened into a draw list with
// the bounds of the building (the ground plane left out, so camera paths frame what matters).
#pragma once
#include "draw_list.hpp"

#include <rrc/result.hpp>

#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <vector>

namespace rrc::demo {

struct DrawScene {
    std::vector<DrawCall> draws;
    glm::dvec3 boundsMin{0.0}, boundsMax{0.0};
    std::string name;
    std::shared_ptr<void> owner;   // keeps the GL objects the draws name alive
};

// `path` is a .gltf/.glb file, or "procedural".
Result<DrawScene> loadDrawScene(const std::string& path);

} // namespace rrc::demo
