// Scenes and demo runners of rrc-bench.
#pragma once
#include "bench_common.hpp"

#include "support/scene_draws.hpp"

#include <rrc/shader.hpp>


namespace rrc::bench {

using BenchScene = demo::DrawScene;

// The demos' shaders (demos/<name>/shaders/*), named "<name>/shaders/<file>".
std::span<const EmbeddedFile> demoShaders();

std::vector<Record> runStereo(const Options& options, const BenchScene& scene, ShaderLibrary& library);

} // namespace rrc::bench
