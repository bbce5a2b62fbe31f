// What the accumulation GL tests share: the renderer at 128x96 with a cheap (2-octave) marble over
// the procedural colonnade, read-backs, and RMSE between two of them.
#pragma once
#include "support/gl_test.hpp"

#include "accumulation/accumulation_renderer.hpp"
#include "support/procedural.hpp"
#include "support/timing.hpp"

#include <rrc/projection.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace rrc::accumulation {
std::span<const EmbeddedFile> shaders();
}

namespace rrc::test {

class AccumulationFixture : public GLTest {
protected:
    static constexpr int kWidth = 128, kHeight = 96;

    void SetUp() override {
        GLTest::SetUp();
        library.add(demo::supportShaders());
        library.add(accumulation::shaders());
        ASSERT_TRUE(renderer.init(kWidth, kHeight, library, {.octaves = 2}).ok());
        scene = demo::makeColonnade(4);
    }
    void TearDown() override {
        renderer = {};
        scene = {};
        GLTest::TearDown();
    }

    static glm::dmat4 projection() { return perspectiveReversedZ(0.9, double(kWidth) / kHeight, 0.1); }

    // A kWidth x kHeight RGBA float texture's pixels.
    static std::vector<glm::vec4> pixels(GLuint texture) {
        std::vector<glm::vec4> p(size_t(kWidth * kHeight));
        glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(p.size() * sizeof(glm::vec4)), p.data());
        return p;
    }

    static double rmse(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
        double sum = 0;
        for (size_t i = 0; i < a.size(); ++i) {
            const glm::dvec3 d = glm::dvec3(a[i]) - glm::dvec3(b[i]);
            sum += glm::dot(d, d) / 3.0;
        }
        return std::sqrt(sum / double(a.size()));
    }

    accumulation::AccumulationRenderer renderer;
    demo::ProceduralScene scene;
};

} // namespace rrc::test
