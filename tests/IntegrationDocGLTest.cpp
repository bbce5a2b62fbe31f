// docs/integration.md is compiled (its code blocks are extracted at configure time) and run here:
// the example renderer must produce hits after a small camera move and fresh shading where the
// object moved.
#include "support/gl_test.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "doc_example.cpp"

namespace rrc::doc {
std::span<const EmbeddedFile> integrationShaders();
}

namespace rrc::test {
namespace {

class IntegrationDoc : public GLTest {};

TEST_F(IntegrationDoc, ExampleRendererCachesAcrossFrames) {
    library.add(rrc::doc::integrationShaders());
    ExampleRenderer renderer;
    ASSERT_TRUE(renderer.init(160, 120, library).ok());
    const glm::dmat4 model = glm::scale(glm::translate(glm::dmat4(1.0), {0, 0, -3}), {4, 4, 1});
    const Stats first = renderer.frame({0, 0, 0}, model, model);
    EXPECT_EQ(first.hits, 0u);
    const Stats second = renderer.frame({0.05, 0.02, 0}, model, model);
    std::printf("integration example: frame 2 hit rate %.3f\n", second.hitRate());
    EXPECT_GT(second.hitRate(), 0.95);
    EXPECT_GT(second.misses, 0u);   // the strip that came into view
}

} // namespace
} // namespace rrc::test
