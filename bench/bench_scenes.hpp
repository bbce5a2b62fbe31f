// Demo runners of rrc-bench. Each bench/<demo>_bench.cpp registers itself with a static
// DemoRegistration; rrc_bench.cpp runs the registered demos in `order`, those --demos names.
#pragma once
#include "bench_common.hpp"

#include "support/scene_draws.hpp"

#include <rrc/shader.hpp>

#include <functional>

namespace rrc::bench {

using BenchScene = demo::DrawScene;

// The demos' shaders (demos/<name>/shaders/*), named "<name>/shaders/<file>".
std::span<const EmbeddedFile> demoShaders();

// A demo's rows for results.json; an empty vector means the demo failed (after saying why on stderr).
using DemoRunner = std::function<std::vector<Record>(const Options&, ShaderLibrary&)>;

struct DemoEntry {
    std::string name;   // the results.json "demo" key: stereo, motion_blur, depth_of_field, shadows, bump_env
    int order = 0;      // run order in rrc-bench (and so in the report)
    DemoRunner run;
};

const std::vector<DemoEntry>& registeredDemos();

struct DemoRegistration {
    DemoRegistration(std::string name, int order, DemoRunner run);
};

// Loads a glTF scene (or "procedural"); says why on stderr when it fails.
std::optional<BenchScene> loadBenchScene(const std::string& path);

} // namespace rrc::bench
