// Shared by the demos and benchmarks: frame timing (wall clock around glFinish, since GL timer
// queries are meaningless on llvmpipe; warm-up frames first; median and min) and the permutation
// texture of the expensive Perlin shader (shaders/perlin.glsl).
#pragma once
#include <rrc/embedded.hpp>
#include <rrc/gl_object.hpp>

#include <functional>

namespace rrc::demo {

struct Timing {
    double median = 0;   // ms
    double min = 0;      // ms
    int frames = 0;
};

Timing timeFrames(const std::function<void()>& frame, int warmup, int frames);

// The Perlin permutation table of support/shaders/perlin.glsl: 512x1 R8UI holding a seeded
// shuffle of 0..255 twice.
Texture permutationTexture(uint32_t seed);

// The demos' shared GLSL (support/shaders/*), named "support/shaders/<file>".
std::span<const EmbeddedFile> supportShaders();

} // namespace rrc::demo
