// Scenes and demo runners of rrc-bench.
#pragma once
#include "bench_common.hpp"

#include "support/procedural.hpp"

#include <rrc/shader.hpp>

#include <glm/vec3.hpp>

#include <memory>

namespace rrc::bench {

struct SceneBounds {
    glm::dvec3 min{0.0}, max{0.0};
};

// The scene every demo draws: a draw list plus whatever owns its GL objects.
struct BenchScene {
    std::vector<demo::DrawCall> draws;
    SceneBounds bounds;
    std::shared_ptr<void> owner;
    std::string name;
};

// `path` names a .gltf/.glb file, or "procedural" for the built-in colonnade.
Result<BenchScene> loadBenchScene(const std::string& path);

// The glTF path (bench_gltf.cpp).
Result<BenchScene> loadGltfBenchScene(const std::string& path);

// The demos' shaders (demos/<name>/shaders/*), named "<name>/shaders/<file>".
std::span<const EmbeddedFile> demoShaders();

std::vector<Record> runStereo(const Options& options, const BenchScene& scene, ShaderLibrary& library);

} // namespace rrc::bench
