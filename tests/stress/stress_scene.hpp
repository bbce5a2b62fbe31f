// A configurable cache scene for the stress suite: the quads, cameras and readbacks of
// support/cache_scene.hpp, with the fragment shading supplied by each test as a GLSL body that
// defines
//   vec4 onMiss();                          // the value of a pixel the cache could not supply
//   vec4 onHit(rrc_Lookup l, vec4 cached);  // the value of a hit, given the resampled payload
// It may read v_world (world position, float), v_local (quad coordinates in [-1, 1]), u_frame
// (the cache frame), u_params and u_params2 (set by the test), and everything the rrc snippets
// offer (rrc/lookup.frag and rrc/blend.glsl are included).
#pragma once
#include "support/cache_scene.hpp"

#include <string>

namespace rrc::test {

class StressScene : public QuadScene {
public:
    StressScene(const Cache& cache, const std::string& body, std::vector<Define> extra = {});

    // beginFrame + render + endFrame with `view` and `projection` (FrameDesc's own are replaced).
    // Returns false when beginFrame failed.
    bool frame(Cache& cache, ControlFlow flow, const glm::dmat4& view, const glm::dmat4& projection,
               std::span<const Object> objects, FrameDesc frameDesc = {});
    // The same with a Camera (its projection for the cache's aspect and depth convention).
    bool frame(Cache& cache, ControlFlow flow, const Camera& camera, std::span<const Object> objects,
               FrameDesc frameDesc = {});

    glm::vec4 params{0.0f}, params2{0.0f};

private:
    void setFrameUniforms(GLuint program, uint32_t frame) const override;
};

// Reads VmRSS from /proc/self/status, in KiB (0 when unavailable).
long residentKiB();

// A GL enum's name for the formats the stress tests use ("GL_RGBA16F").
const char* formatName(GLenum format);

} // namespace rrc::test
