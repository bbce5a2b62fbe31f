// Per-frame pose evaluation: locals -> world (double) -> joint matrices, with the previous frame
// kept by swapping buffers rather than copying.
#include "scene_state.hpp"

#include "animation.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::scene {

SceneState::SceneState(const Scene& scene) : scene_(&scene) {
    locals_.reserve(scene.nodes.size());
    for (const Node& node : scene.nodes) locals_.push_back(node.local);
    update();
    resetHistory();
}

void SceneState::beginFrame() {
    world_.swap(previousWorld_);
    skins_.swap(previousSkins_);
    for (size_t i = 0; i < locals_.size(); ++i) locals_[i] = scene_->nodes[i].local;
    ++frame_;
}

void SceneState::advance(double time, const Animation* clip, bool loop) {
    beginFrame();
    if (clip) sampleAnimation(*clip, time, loop, locals_);
    update();
}

void SceneState::update() {
    localMatrices_.resize(locals_.size());
    for (size_t i = 0; i < locals_.size(); ++i) localMatrices_[i] = locals_[i].toMatrix();
    computeWorld(*scene_, localMatrices_, world_);
    computeSkins();
}

void SceneState::resetHistory() {
    previousWorld_ = world_;
    previousSkins_ = skins_;
}

void SceneState::computeSkins() {
    skins_.resize(scene_->skins.size());
    for (size_t s = 0; s < skins_.size(); ++s) {
        const Skin& skin = scene_->skins[s];
        SkinPose& pose = skins_[s];
        const uint32_t root = skin.skeleton >= 0 ? uint32_t(skin.skeleton) : skin.joints.front();
        // Translation only: an anchor with rotation or scale could be singular (a joint scaled to 0).
        pose.anchor = glm::dvec3(world_[root][3]);
        const glm::dmat4 toAnchor = glm::translate(glm::dmat4(1.0), -pose.anchor);
        pose.world.resize(skin.joints.size());
        pose.relative.resize(skin.joints.size());
        for (size_t j = 0; j < skin.joints.size(); ++j) {
            pose.world[j] = world_[skin.joints[j]] * skin.inverseBind[j];
            pose.relative[j] = glm::mat4(toAnchor * pose.world[j]);
        }
    }
}

glm::dmat4 SceneState::skinModel(size_t index) const { return glm::translate(glm::dmat4(1.0), skins_[index].anchor); }

glm::dmat4 SceneState::previousSkinModel(size_t index) const {
    return glm::translate(glm::dmat4(1.0), previousSkins_[index].anchor);
}

glm::dvec3 skinPoint(const SkinPose& pose, const glm::dvec3& position, const glm::u16vec4& joints, const glm::dvec4& weights) {
    glm::dvec4 sum(0.0);
    for (int i = 0; i < 4; ++i) sum += weights[i] * (pose.world[joints[i]] * glm::dvec4(position, 1.0));
    return glm::dvec3(sum);
}

} // namespace rrc::scene
