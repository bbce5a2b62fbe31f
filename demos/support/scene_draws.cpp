// Scenes for the demos and rrc-bench: glTF through rrc_scene, or the procedural colonnade.
#include "scene_draws.hpp"

#include "procedural.hpp"

#include <gpu_scene.hpp>
#include <scene.hpp>
#include <scene_state.hpp>

#include <glm/glm.hpp>

namespace rrc::demo {
namespace {

struct GltfOwner {
    scene::Scene scene;
    scene::GpuScene gpu;
    std::unique_ptr<scene::SceneState> state;
};

void grow(DrawScene& s, const glm::dmat4& model, glm::dvec3 lo, glm::dvec3 hi) {
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 local(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z);
        const glm::dvec3 p(model * glm::dvec4(local, 1.0));
        s.boundsMin = glm::min(s.boundsMin, p);
        s.boundsMax = glm::max(s.boundsMax, p);
    }
}

Result<DrawScene> loadGltf(const std::string& path) {
    auto loaded = scene::loadScene(path);
    if (!loaded) return loaded.error();
    auto owner = std::make_shared<GltfOwner>();
    owner->scene = std::move(loaded).value();
    auto gpu = scene::GpuScene::upload(owner->scene);
    if (!gpu) return gpu.error();
    owner->gpu = std::move(gpu).value();
    owner->state = std::make_unique<scene::SceneState>(owner->scene);
    DrawScene s{{}, glm::dvec3(1e300), glm::dvec3(-1e300), path, owner};
    owner->gpu.forEachDraw(*owner->state, [&](const scene::DrawItem& item) {
        const auto& primitive = owner->scene.meshes[item.mesh].primitives[item.primitive];
        const glm::vec4 color = item.material ? item.material->baseColorFactor : glm::vec4(1.0f);
        s.draws.push_back({item.vertexArray, item.indexCount, GL_UNSIGNED_INT, item.world, item.previousWorld, color,
                           static_cast<uint32_t>(s.draws.size() + 1)});
        const std::string& node = owner->scene.nodes[item.node].name;
        if (node.find("ground") == std::string::npos && node.find("Ground") == std::string::npos)
            grow(s, item.world, primitive.boundsMin, primitive.boundsMax);
    });
    if (s.draws.empty()) return fail(LogId::SceneInvalid, path + ": the scene draws nothing");
    return s;
}

} // namespace

Result<DrawScene> loadDrawScene(const std::string& path) {
    if (path != "procedural") return loadGltf(path);
    auto scene = std::make_shared<ProceduralScene>(makeColonnade());
    DrawScene s{scene->draws, glm::dvec3(1e300), glm::dvec3(-1e300), "procedural colonnade", scene};
    for (size_t i = 1; i < scene->draws.size(); ++i)   // draw 0 is the ground slab
        grow(s, scene->draws[i].model, glm::dvec3(-1.0), glm::dvec3(1.0));
    return s;
}

} // namespace rrc::demo
