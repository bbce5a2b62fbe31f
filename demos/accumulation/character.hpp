// A skinned glTF character (assets/character.glb) for the accumulation demos: loaded, uploaded,
// and posed per sample (clip time plus a placement of its root node), so that the previous pose
// held by scene::SceneState is always the previous sample's, as the cache-time bones need.
#pragma once
#include "scene/gpu_scene.hpp"

#include <memory>
#include <string>

namespace rrc::accumulation {

class Character {
public:
    // `placementNode`: the node moved by pose()'s placement (the character's root); `clip`: the
    // animation played.
    static Result<Character> load(const std::string& path, const std::string& placementNode = "heroine",
                                  const std::string& clip = "run");

    // A new sample: the previous pose becomes the cache-time one; the clip at `time` seconds
    // (looping), the placement node at `placement` (its rest transform replaced).
    void pose(double time, const glm::dmat4& placement);
    void forEachDraw(const std::function<void(const scene::DrawItem&)>& fn) const;
    const scene::Scene& scene() const { return data_->scene; }

private:
    struct Data {
        scene::Scene scene;
        scene::GpuScene gpu;
        std::unique_ptr<scene::SceneState> state;
        int placementNode = 0;
        int clip = 0;
    };
    std::unique_ptr<Data> data_;   // stable address: SceneState points at the Scene
};

} // namespace rrc::accumulation
