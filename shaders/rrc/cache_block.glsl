// The cache-time state every lookup reads, uploaded once per frame by rrc::Cache::beginFrame.
#ifndef RRC_CACHE_BLOCK_GLSL
#define RRC_CACHE_BLOCK_GLSL

#ifndef RRC_CACHE_BINDING
#define RRC_CACHE_BINDING 7
#endif

layout(std140, binding = RRC_CACHE_BINDING) uniform rrc_CacheBlock {
    vec4 rrc_cacheSize;    // width, height, 1/width, 1/height
    vec4 rrc_cacheDepth;   // cache-time near, far (<= 0: infinite), reversed-Z (0/1), valid (0/1)
    vec4 rrc_tolerance;    // relative depth tolerance, slope tolerance, max scale (0: off), lambda
    uvec4 rrc_frameInfo;   // frame, refresh policy, refresh period, refresh block size
    vec4 rrc_refreshInfo;  // random refresh fraction, unused x3
};

#endif
