// glTF scenes for rrc-bench (until the scene layer lands, a clear error).
#include "bench_scenes.hpp"

namespace rrc::bench {

Result<BenchScene> loadGltfBenchScene(const std::string& path) {
    return fail(LogId::SceneLoadFailed, path + ": glTF scenes are not wired into rrc-bench yet; use --scene procedural");
}

} // namespace rrc::bench
