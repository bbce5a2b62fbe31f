// Refresh schedule (rrc::RefreshPolicy): whether this screen pixel is recomputed this frame.
// Mirrors rrc::refreshScheduled in src/refresh.cpp bit for bit. Compiled into lookups only with
// RRC_REFRESH (CacheDesc::refresh): llvmpipe pays ~3 ms per 1024x768 pass for it even when off.
#ifndef RRC_REFRESH_GLSL
#define RRC_REFRESH_GLSL
#include <rrc/cache_block.glsl>
#include <rrc/hash.glsl>

bool rrc_refreshScheduled(uvec2 pixel) {
    uint policy = rrc_frameInfo.y;
    if (policy == 0u) return false;
    if (policy == 1u) return true;
    uvec2 block = pixel / max(rrc_frameInfo.w, 1u);
    if (policy == 2u) return rrc_hashToUnit(rrc_hash(uvec3(block, rrc_frameInfo.x))) < rrc_refreshInfo.x;
    uint period = max(rrc_frameInfo.z, 1u);
    return rrc_hash(uvec3(block, 0x9e3779b9u)) % period == rrc_frameInfo.x % period;
}

#endif
