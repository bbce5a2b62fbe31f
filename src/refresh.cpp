// CPU mirror of shaders/rrc/refresh.glsl and hash.glsl (tests compare the two bit for bit).
#include <rrc/refresh.hpp>

#include <algorithm>

namespace rrc {

uint32_t hash3(uint32_t x, uint32_t y, uint32_t z) {
    uint32_t h = (x * 0x8da6b343u) ^ (y * 0xd8163841u) ^ (z * 0xcb1ab31fu);
    h ^= h >> 16; h *= 0x7feb352du;
    h ^= h >> 15; h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

bool refreshScheduled(const RefreshDesc& desc, uint32_t x, uint32_t y, uint32_t frame) {
    switch (desc.policy) {
    case RefreshPolicy::None: return false;
    case RefreshPolicy::Full: return true;
    case RefreshPolicy::Random: {
        const uint32_t b = std::max(desc.blockSize, 1u);
        const float unit = static_cast<float>(hash3(x / b, y / b, frame) >> 8) * (1.0f / 16777216.0f);
        return unit < desc.fraction;
    }
    case RefreshPolicy::RoundRobin: {
        const uint32_t b = std::max(desc.blockSize, 1u), period = std::max(desc.period, 1u);
        return hash3(x / b, y / b, 0x9e3779b9u) % period == frame % period;
    }
    }
    return false;
}

} // namespace rrc
