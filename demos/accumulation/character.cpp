#include "character.hpp"

#include "scene/animation.hpp"

namespace rrc::accumulation {

Result<Character> Character::load(const std::string& path, const std::string& placementNode, const std::string& clip) {
    auto loaded = scene::loadScene(path);
    if (!loaded) return loaded.error();
    Character c;
    c.data_ = std::make_unique<Data>();
    Data& d = *c.data_;
    d.scene = std::move(loaded).value();
    d.placementNode = d.clip = -1;
    for (size_t i = 0; i < d.scene.nodes.size(); ++i)
        if (d.scene.nodes[i].name == placementNode) d.placementNode = int(i);
    for (size_t i = 0; i < d.scene.animations.size(); ++i)
        if (d.scene.animations[i].name == clip) d.clip = int(i);
    if (d.placementNode < 0) return fail(LogId::SceneInvalid, path + ": no node named " + placementNode);
    if (d.clip < 0) return fail(LogId::SceneInvalid, path + ": no animation named " + clip);
    auto gpu = scene::GpuScene::upload(d.scene);
    if (!gpu) return gpu.error();
    d.gpu = std::move(gpu).value();
    d.state = std::make_unique<scene::SceneState>(d.scene);
    return c;
}

void Character::pose(double time, const glm::dmat4& placement) {
    Data& d = *data_;
    d.state->beginFrame();
    const scene::Animation& clip = d.scene.animations[size_t(d.clip)];
    scene::sampleAnimation(clip, clip.start + time, true, d.state->locals());
    d.state->locals()[size_t(d.placementNode)] = scene::Transform{.matrix = placement};
    d.state->update();
    d.gpu.updateJoints(*d.state);
}

void Character::forEachDraw(const std::function<void(const scene::DrawItem&)>& fn) const {
    data_->gpu.forEachDraw(*data_->state, fn);
}

} // namespace rrc::accumulation
