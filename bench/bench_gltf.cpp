// glTF scenes for rrc-bench through rrc_scene: loaded and validated, uploaded, posed once (the
// benchmark scenes are static), flattened into a draw list.
#include "bench_scenes.hpp"

#include <gpu_scene.hpp>
#include <scene.hpp>
#include <scene_state.hpp>

#include <glm/glm.hpp>

namespace rrc::bench {
namespace {

struct GltfOwner {
    scene::Scene scene;
    scene::GpuScene gpu;
    std::unique_ptr<scene::SceneState> state;
};

} // namespace

Result<BenchScene> loadGltfBenchScene(const std::string& path) {
    auto loaded = scene::loadScene(path);
    if (!loaded) return loaded.error();
    auto owner = std::make_shared<GltfOwner>();
    owner->scene = std::move(loaded).value();
    auto gpu = scene::GpuScene::upload(owner->scene);
    if (!gpu) return gpu.error();
    owner->gpu = std::move(gpu).value();
    owner->state = std::make_unique<scene::SceneState>(owner->scene);
    BenchScene s{{}, {glm::dvec3(1e300), glm::dvec3(-1e300)}, owner, path};
    owner->gpu.forEachDraw(*owner->state, [&](const scene::DrawItem& item) {
        const auto& primitive = owner->scene.meshes[item.mesh].primitives[item.primitive];
        glm::vec4 color(1.0f);
        if (item.material) color = item.material->baseColorFactor;
        s.draws.push_back({item.vertexArray, item.indexCount, GL_UNSIGNED_INT, item.world, item.previousWorld, color,
                           static_cast<uint32_t>(s.draws.size() + 1)});
        // Camera paths frame the building, not the ground plane that runs to the horizon.
        const std::string& node = owner->scene.nodes[item.node].name;
        if (node.find("ground") != std::string::npos || node.find("Ground") != std::string::npos) return;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 local(corner & 1 ? primitive.boundsMax.x : primitive.boundsMin.x,
                                   corner & 2 ? primitive.boundsMax.y : primitive.boundsMin.y,
                                   corner & 4 ? primitive.boundsMax.z : primitive.boundsMin.z);
            const glm::dvec3 p(item.world * glm::dvec4(local, 1.0));
            s.bounds.min = glm::min(s.bounds.min, p);
            s.bounds.max = glm::max(s.bounds.max, p);
        }
    });
    if (s.draws.empty()) return fail(LogId::SceneInvalid, path + ": the scene draws nothing");
    return s;
}

} // namespace rrc::bench
