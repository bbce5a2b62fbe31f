#include "timing.hpp"

#include <rrc/gl.hpp>
#include <rrc/refresh.hpp>

#include <algorithm>
#include <chrono>
#include <vector>

namespace rrc::demo {

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

Texture permutationTexture(uint32_t seed) {
    std::vector<uint8_t> table(512);
    for (int i = 0; i < 256; ++i) table[i] = static_cast<uint8_t>(i);
    for (int i = 255; i > 0; --i) std::swap(table[i], table[hash3(static_cast<uint32_t>(i), seed, 0x51ed27u) % (i + 1)]);
    std::copy(table.begin(), table.begin() + 256, table.begin() + 256);
    Texture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_R8UI, 512, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(t.id(), 0, 0, 0, 512, 1, GL_RED_INTEGER, GL_UNSIGNED_BYTE, table.data());
    return t;
}

} // namespace rrc::demo
