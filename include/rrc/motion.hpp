// Cache-time state on the CPU: previous model and skinning matrices per object, and matrix
// composition in double precision so that scenes far from the origin keep their precision
// (the view and model translations cancel in double before anything is rounded to float).
#pragma once
#include <glm/mat4x4.hpp>

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace rrc {

struct ViewState {
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};
};

// What a draw needs: the current and cache-time object-to-clip matrices (float, for the GPU),
// and the current object-to-view matrix (for lighting in view space).
struct DrawMatrices {
    glm::mat4 modelViewProj{1.0f};
    glm::mat4 prevModelViewProj{1.0f};
    glm::mat4 modelView{1.0f};
};

DrawMatrices composeDrawMatrices(const ViewState& current, const ViewState& cacheTime,
                                 const glm::dmat4& model, const glm::dmat4& prevModel);

// Remembers each object's model matrix from the previous frame.
class MotionHistory {
public:
    // Records this frame's model matrix and returns the one of the previous frame (the same
    // matrix for an object seen for the first time). `moved` reports whether they differ.
    glm::dmat4 update(uint32_t objectId, const glm::dmat4& model, bool* moved = nullptr);
    // Call once per frame after all updates: objects not updated this frame are forgotten.
    void endFrame();
    bool anyMoved() const { return anyMoved_; }

private:
    struct Entry { glm::dmat4 model; uint32_t frameSeen; };
    std::unordered_map<uint32_t, Entry> entries_;
    uint32_t frame_ = 0;
    bool anyMoved_ = false;
};

// Current and previous bone matrices of one skinned mesh.
class BoneHistory {
public:
    void update(std::span<const glm::mat4> bones);  // first call: previous = current
    std::span<const glm::mat4> current() const { return current_; }
    std::span<const glm::mat4> previous() const { return previous_; }
    bool moved() const { return current_ != previous_; }

private:
    std::vector<glm::mat4> current_, previous_;
};

} // namespace rrc
