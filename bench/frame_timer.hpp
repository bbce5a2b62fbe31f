// Frame timing for benchmarks: wall clock around glFinish (GL timer queries are meaningless on
// llvmpipe), warm-up frames first, median and min of the measured frames.
#pragma once
#include <functional>

namespace rrc::bench {

struct Timing {
    double median = 0;   // ms
    double min = 0;      // ms
    int frames = 0;
};

Timing timeFrames(const std::function<void()>& frame, int warmup, int frames);

} // namespace rrc::bench
