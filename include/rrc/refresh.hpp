// Refresh policies: which screen pixels are recomputed this frame although the cache could
// supply them, so cached values cannot grow arbitrarily old. The GLSL in shaders/rrc/refresh.glsl
// and refreshScheduled() below compute the same schedule bit for bit.
#pragma once
#include <cstdint>

namespace rrc {

enum class RefreshPolicy : uint32_t {
    None = 0,        // never refresh
    Full = 1,        // refresh everything this frame (a flush)
    Random = 2,      // each block refreshes with probability `fraction`, independently per frame
    RoundRobin = 3,  // each block belongs to one of `period` groups; group (frame % period)
                     // refreshes, so no pixel goes more than `period` frames without a refresh
};

struct RefreshDesc {
    RefreshPolicy policy = RefreshPolicy::None;
    float fraction = 0.1f;    // Random: expected fraction of blocks refreshed per frame
    uint32_t period = 8;      // RoundRobin: frames between refreshes of a block (>= 1)
    uint32_t blockSize = 4;   // 1, 2, 4 or 8 pixels; PLATFORM.md: below 4x4 the scattered
                              // misses cost llvmpipe (and GPUs) far more than clustered ones
};

// 32-bit integer hash shared with GLSL (rrc_hash in shaders/rrc/hash.glsl).
uint32_t hash3(uint32_t x, uint32_t y, uint32_t z);

// True when pixel (x, y) (GL window coordinates) is refreshed on `frame`.
bool refreshScheduled(const RefreshDesc& desc, uint32_t x, uint32_t y, uint32_t frame);

} // namespace rrc
