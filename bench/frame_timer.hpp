// Frame timing for benchmarks: wall clock around glFinish (GL timer queries are meaningless on
// llvmpipe), warm-up frames first, median and min of the measured frames.
#pragma once
#include <rrc/gl_object.hpp>

#include <functional>

namespace rrc::bench {

struct Timing {
    double median = 0;   // ms
    double min = 0;      // ms
    int frames = 0;
};

Timing timeFrames(const std::function<void()>& frame, int warmup, int frames);

// The Perlin permutation table of bench/shaders/perlin.glsl: 512x1 R8UI holding a seeded
// shuffle of 0..255 twice.
Texture permutationTexture(uint32_t seed);

} // namespace rrc::bench
