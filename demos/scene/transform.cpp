// Node transforms and the hierarchy: local matrices, parent links, a parents-first order, and
// world matrices composed in double precision.
#include "scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cassert>

namespace rrc::scene {

glm::dmat4 Transform::toMatrix() const {
    if (matrix) return *matrix;
    return glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) * glm::scale(glm::dmat4(1.0), scale);
}

void Scene::linkHierarchy() {
    for (Node& node : nodes) node.parent = kNone;
    for (size_t i = 0; i < nodes.size(); ++i)
        for (uint32_t child : nodes[i].children) {
            assert(child < nodes.size() && nodes[child].parent == kNone && "a child index is invalid or has two parents");
            nodes[child].parent = int(i);
        }
    // Depth-first from every parentless node; an explicit stack because hierarchies can be deep.
    order.clear();
    std::vector<uint32_t> stack;
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].parent != kNone) continue;
        stack.push_back(uint32_t(i));
        while (!stack.empty()) {
            const uint32_t node = stack.back();
            stack.pop_back();
            order.push_back(node);
            for (uint32_t child : nodes[node].children) stack.push_back(child);
        }
    }
    assert(order.size() == nodes.size() && "the node hierarchy has a cycle");
}

void computeWorld(const Scene& scene, const std::vector<glm::dmat4>& locals, std::vector<glm::dmat4>& world) {
    assert(locals.size() == scene.nodes.size());
    world.resize(scene.nodes.size());
    for (uint32_t node : scene.order) {
        const int parent = scene.nodes[node].parent;
        world[node] = parent == kNone ? locals[node] : world[size_t(parent)] * locals[node];
    }
}

} // namespace rrc::scene
