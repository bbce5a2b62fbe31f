// Scene loading for rrc-bench: the procedural colonnade, or a glTF file through rrc_scene.
#include "bench_scenes.hpp"

#include <glm/glm.hpp>

namespace rrc::bench {
namespace {

SceneBounds boundsOf(const std::vector<demo::DrawCall>& draws) {
    SceneBounds b{glm::dvec3(1e300), glm::dvec3(-1e300)};
    for (const auto& d : draws)
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec4 p = d.model * glm::dvec4(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1, 1);
            b.min = glm::min(b.min, glm::dvec3(p));
            b.max = glm::max(b.max, glm::dvec3(p));
        }
    return b;
}

} // namespace

Result<BenchScene> loadBenchScene(const std::string& path) {
    if (path == "procedural") {
        auto scene = std::make_shared<demo::ProceduralScene>(demo::makeColonnade());
        BenchScene s{scene->draws, {}, scene, "procedural colonnade"};
        s.bounds = boundsOf(scene->draws);
        // The ground slab is far larger than the building: frame the building.
        s.bounds = boundsOf(std::vector(scene->draws.begin() + 1, scene->draws.end()));
        return s;
    }
    return loadGltfBenchScene(path);
}

} // namespace rrc::bench
