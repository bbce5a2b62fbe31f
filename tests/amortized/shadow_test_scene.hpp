// The shadow tests' scene: a 40 m ground square at y = 0 and an occluding slab at y = 2 over
// x < 0, the sun straight above; the camera stands at (8, 1, 0) under the slab's height looking
// towards -x, so the ground it sees is lit for x > 0 and shadowed for x < 0 (the penumbra is the
// PCF radius either side of x = 0).
#pragma once
#include "support/procedural.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <vector>

namespace rrc::test {

struct ShadowTestScene {
    std::vector<demo::MeshBuffers> meshes;
    std::vector<demo::DrawCall> draws;
    glm::dvec3 boundsMin{-20.0, 0.0, -20.0}, boundsMax{20.0, 2.0, 20.0};
    glm::dmat4 view = glm::lookAt(glm::dvec3(8.0, 1.0, 0.0), glm::dvec3(-3.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0));
    glm::dmat4 parkedCaster = glm::translate(glm::dmat4(1.0), glm::dvec3(500.0, -500.0, 500.0));   // out of every view

    ShadowTestScene() {
        auto quad = [&](float x0, float x1, float y, float z0, float z1, float ny) {
            const std::vector<float> v = {x0, y, z0, 0, ny, 0, x1, y, z0, 0, ny, 0, x1, y, z1, 0, ny, 0, x0, y, z1, 0, ny, 0};
            meshes.push_back(demo::uploadMesh(v, {0, 1, 2, 0, 2, 3}));
            draws.push_back({.vertexArray = meshes.back().vertexArray.id(), .indexCount = 6, .objectId = uint32_t(draws.size() + 2)});
        };
        quad(-20, 20, 0, -20, 20, 1);
        quad(-20, 0, 2, -20, 20, -1);
    }
};

} // namespace rrc::test
