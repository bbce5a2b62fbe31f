// Double-precision matrix composition and per-object / per-skeleton history.
#include <rrc/motion.hpp>

namespace rrc {

DrawMatrices composeDrawMatrices(const ViewState& current, const ViewState& cacheTime,
                                 const glm::dmat4& model, const glm::dmat4& prevModel) {
    // View * model first, in double: large world translations cancel before rounding to float.
    const glm::dmat4 modelView = current.view * model;
    const glm::dmat4 prevModelView = cacheTime.view * prevModel;
    return {glm::mat4(current.projection * modelView), glm::mat4(cacheTime.projection * prevModelView),
            glm::mat4(modelView)};
}

glm::dmat4 MotionHistory::update(uint32_t objectId, const glm::dmat4& model, bool* moved) {
    auto [it, inserted] = entries_.try_emplace(objectId, Entry{model, frame_});
    const glm::dmat4 previous = inserted ? model : it->second.model;
    const bool changed = !inserted && previous != model;
    it->second = Entry{model, frame_};
    anyMoved_ = anyMoved_ || changed || inserted;
    if (moved) *moved = changed;
    return previous;
}

void MotionHistory::endFrame() {
    std::erase_if(entries_, [&](const auto& e) { return e.second.frameSeen != frame_; });
    ++frame_;
    anyMoved_ = false;
}

void BoneHistory::update(std::span<const glm::mat4> bones) {
    const bool first = current_.empty();
    previous_ = first ? std::vector<glm::mat4>(bones.begin(), bones.end()) : current_;
    current_.assign(bones.begin(), bones.end());
}

} // namespace rrc
