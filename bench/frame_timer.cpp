#include "frame_timer.hpp"

#include <rrc/gl.hpp>

#include <algorithm>
#include <chrono>
#include <vector>

namespace rrc::bench {

Timing timeFrames(const std::function<void()>& frame, int warmup, int frames) {
    for (int i = 0; i < warmup; ++i) frame();
    glFinish();
    std::vector<double> ms;
    for (int i = 0; i < frames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        frame();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    if (ms.empty()) return {};
    std::sort(ms.begin(), ms.end());
    return {ms[ms.size() / 2], ms.front(), frames};
}

} // namespace rrc::bench
