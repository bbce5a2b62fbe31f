// The animated state of a Scene for one frame and the frame before: node world matrices and skin
// joint matrices, current and previous, as the reprojection cache needs them (cache-time
// transforms). Everything is composed in double; only the GPU copies of joints are float.
#pragma once
#include "scene.hpp"

#include <cstdint>
#include <vector>

namespace rrc::scene {

struct SkinPose {
    glm::dvec3 anchor{0.0};               // world position of the skeleton root (or first joint)
    std::vector<glm::dmat4> world;        // per joint: jointWorld * inverseBind (bind space -> world)
    // Per joint: translate(-anchor) * world, in float for the GPU. Relative to the anchor so that
    // skins far from the origin keep their precision; draw them with the model matrix
    // translate(anchor) (SceneState::skinModel), which stays in double until the view cancels it.
    std::vector<glm::mat4> relative;
};

class SceneState {
public:
    // The rest pose of `scene`, which must outlive the state; previous == current.
    explicit SceneState(const Scene& scene);

    const Scene& scene() const { return *scene_; }

    // A new frame: current becomes previous, the pose is the rest pose with `clip` (if any)
    // sampled at `time` seconds, looping or clamped.
    void advance(double time, const Animation* clip = nullptr, bool loop = true);

    // The same in steps, for poses of your own: beginFrame() (current -> previous, locals back to
    // the rest pose), edit locals(), then update().
    void beginFrame();
    std::vector<Transform>& locals() { return locals_; }
    void update();

    // Forgets the motion: previous = current (after a camera cut or a teleport).
    void resetHistory();

    const std::vector<glm::dmat4>& world() const { return world_; }
    const std::vector<glm::dmat4>& previousWorld() const { return previousWorld_; }
    const SkinPose& skin(size_t index) const { return skins_[index]; }
    const SkinPose& previousSkin(size_t index) const { return previousSkins_[index]; }
    glm::dmat4 skinModel(size_t index) const;
    glm::dmat4 previousSkinModel(size_t index) const;
    uint64_t frame() const { return frame_; }   // advance()/beginFrame() calls so far

private:
    void computeSkins();

    const Scene* scene_;
    std::vector<Transform> locals_;
    std::vector<glm::dmat4> localMatrices_, world_, previousWorld_;
    std::vector<SkinPose> skins_, previousSkins_;
    uint64_t frame_ = 0;
};

// Linear blend skinning on the CPU (tests, picking): the world position of bind-space `position`
// with the given joints and weights of `pose`.
glm::dvec3 skinPoint(const SkinPose& pose, const glm::dvec3& position, const glm::u16vec4& joints, const glm::dvec4& weights);

} // namespace rrc::scene
