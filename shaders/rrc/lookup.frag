// Fragment side of the cache lookup: cache coordinates from the interpolated cache-time clip
// position, viewport clipping, the cached-depth test in linear view depth, optional object-id
// key, forced misses and refresh, then payload fetches with the configured resampling.
// Compose programs with rrc::Cache::defines() so the bindings and features match the cache.
#ifndef RRC_LOOKUP_FRAG
#define RRC_LOOKUP_FRAG
#include <rrc/cache_block.glsl>
#include <rrc/depth.glsl>
#include <rrc/refresh.glsl>
#include <rrc/resample.glsl>

#ifndef RRC_PAYLOAD_COUNT
#define RRC_PAYLOAD_COUNT 1
#endif
#ifndef RRC_DEPTH_UNIT
#define RRC_DEPTH_UNIT 8
#endif
#ifndef RRC_PAYLOAD0_UNIT
#define RRC_PAYLOAD0_UNIT 11
#endif
#ifndef RRC_PAYLOAD0_SAMPLER
#define RRC_PAYLOAD0_SAMPLER sampler2D
#endif
#ifndef RRC_PAYLOAD0_FETCH
#define RRC_PAYLOAD0_FETCH rrc_sampleBilinear
#endif

in vec4 rrc_vCachePos;
uniform uint rrc_objectId;    // this draw's object id (rrc::Cache::setDrawUniforms)
uniform uint rrc_drawFlags;   // bit 0: never cache this object

layout(binding = RRC_DEPTH_UNIT) uniform sampler2D rrc_cachedDepth;
layout(binding = RRC_PAYLOAD0_UNIT) uniform RRC_PAYLOAD0_SAMPLER rrc_payload0;
#if RRC_PAYLOAD_COUNT > 1
layout(binding = RRC_PAYLOAD1_UNIT) uniform RRC_PAYLOAD1_SAMPLER rrc_payload1;
#endif
#if RRC_PAYLOAD_COUNT > 2
layout(binding = RRC_PAYLOAD2_UNIT) uniform RRC_PAYLOAD2_SAMPLER rrc_payload2;
#endif
#if RRC_PAYLOAD_COUNT > 3
layout(binding = RRC_PAYLOAD3_UNIT) uniform RRC_PAYLOAD3_SAMPLER rrc_payload3;
#endif
#ifdef RRC_OBJECT_IDS
layout(binding = RRC_ID_UNIT) uniform usampler2D rrc_cachedIds;
layout(location = RRC_ID_LOCATION) out uint rrc_outId;
#endif
#ifdef RRC_AGE
layout(binding = RRC_AGE_UNIT) uniform usampler2D rrc_cachedAge;
layout(location = RRC_AGE_LOCATION) out uint rrc_outAge;
#endif
#ifdef RRC_STATS
layout(location = RRC_OUTCOME_LOCATION) out uint rrc_outOutcome;
#endif

// Outcomes (rrc::Outcome).
const uint RRC_EMPTY = 0u, RRC_HIT = 1u, RRC_OFFSCREEN = 2u, RRC_DISOCCLUDED = 3u,
           RRC_ID_MISMATCH = 4u, RRC_FORCED = 5u, RRC_REFRESHED = 6u, RRC_INVALID = 7u;

struct rrc_Lookup {
    bool hit;
    uint outcome;
    vec2 uv;     // cache texture coordinate
    uint age;    // frames the cached entry has survived (0 without RRC_AGE)
#ifdef RRC_DEPTH_IN_PAYLOAD
    vec4 payload0;   // fetched once for the depth test and reused by rrc_fetchPayload0 (hits)
#endif
};

#ifndef RRC_DEPTH_CHANNEL
#define RRC_DEPTH_CHANNEL a
#endif

// Linear view depth of the cache entry at `uv` (with RRC_DEPTH_IN_PAYLOAD the caller reads it
// from the payload fetch instead).
float rrc_cachedLinearDepth(vec2 uv) {
#ifdef RRC_DEPTH_IN_PAYLOAD
    return RRC_PAYLOAD0_FETCH(rrc_payload0, uv).RRC_DEPTH_CHANNEL;
#else
#ifdef RRC_NEAREST_DEPTH
    float d = rrc_sampleNearest(rrc_cachedDepth, uv).r;
#else
    float d = textureLod(rrc_cachedDepth, uv, 0.0).r;
#endif
    return rrc_linearDepth(d, rrc_cacheDepth.x, rrc_cacheDepth.y, rrc_cacheDepth.z > 0.5);
#endif
}

// Linear view depth of the current fragment (perspective: 1 / gl_FragCoord.w), e.g. to store
// in payload 0's last channel (alpha, or green for RG formats) with RRC_DEPTH_IN_PAYLOAD.
float rrc_currentLinearDepth() { return 1.0 / gl_FragCoord.w; }

// The lookup. `forceMiss` is the caller's own predicate (e.g. a saturated highlight).
rrc_Lookup rrc_lookup(bool forceMiss) {
    rrc_Lookup l;
    l.hit = false;
    l.age = 0u;
#ifdef RRC_DEPTH_IN_PAYLOAD
    l.payload0 = vec4(0.0);
#endif
    vec4 p = rrc_vCachePos;
    // For a perspective cache-time projection, clip w is the expected linear view depth.
    float expected = p.w;
    // Derivatives before any branch: they need all pixels of the quad.
    float slope = fwidth(expected);
    l.uv = p.xy / p.w * 0.5 + 0.5;
    bool scaleMiss = false;
#ifdef RRC_MAX_SCALE
    {
        vec2 dx = dFdx(l.uv) * rrc_cacheSize.xy, dy = dFdy(l.uv) * rrc_cacheSize.xy;
        float big = max(length(dx), length(dy)), small = min(length(dx), length(dy));
        scaleMiss = big > rrc_tolerance.z || small * rrc_tolerance.z < 1.0;
    }
#endif
    if (rrc_cacheDepth.w < 0.5) {
        l.outcome = RRC_INVALID;
#ifdef RRC_REFRESH
    } else if (rrc_refreshScheduled(uvec2(gl_FragCoord.xy))) {
        l.outcome = RRC_REFRESHED;
#endif
    } else if (forceMiss || (rrc_drawFlags & 1u) != 0u || scaleMiss) {
        l.outcome = RRC_FORCED;
    } else if (p.w <= 0.0 || any(lessThan(l.uv, vec2(0.0))) || any(greaterThan(l.uv, vec2(1.0)))) {
        l.outcome = RRC_OFFSCREEN;
    } else {
#ifdef RRC_DEPTH_IN_PAYLOAD
        l.payload0 = RRC_PAYLOAD0_FETCH(rrc_payload0, l.uv);
        float cached = l.payload0.RRC_DEPTH_CHANNEL;
#else
        float cached = rrc_cachedLinearDepth(l.uv);
#endif
        float tolerance = rrc_tolerance.x * expected + rrc_tolerance.y * slope;
        // Written so that NaN or infinite depths fail the test.
        if (!(abs(cached - expected) <= tolerance)) {
            l.outcome = RRC_DISOCCLUDED;
        } else {
            l.outcome = RRC_HIT;
#ifdef RRC_OBJECT_IDS
            if (rrc_sampleNearest(rrc_cachedIds, l.uv).r != rrc_objectId) l.outcome = RRC_ID_MISMATCH;
#endif
        }
    }
    l.hit = l.outcome == RRC_HIT;
#ifdef RRC_AGE
    if (l.hit) l.age = rrc_sampleNearest(rrc_cachedAge, l.uv).r;
#endif
    return l;
}

rrc_Lookup rrc_lookup() { return rrc_lookup(false); }

#ifdef RRC_DEPTH_IN_PAYLOAD
#define rrc_fetchPayload0(l) ((l).payload0)
#else
#define rrc_fetchPayload0(l) RRC_PAYLOAD0_FETCH(rrc_payload0, (l).uv)
#endif
#define rrc_fetchPayload1(l) RRC_PAYLOAD1_FETCH(rrc_payload1, (l).uv)
#define rrc_fetchPayload2(l) RRC_PAYLOAD2_FETCH(rrc_payload2, (l).uv)
#define rrc_fetchPayload3(l) RRC_PAYLOAD3_FETCH(rrc_payload3, (l).uv)

// Writes the cache's own targets (object id, age, outcome) for this fragment. Call it from
// every pass that writes colour into the cache.
void rrc_writeCache(rrc_Lookup l) {
#ifdef RRC_OBJECT_IDS
    rrc_outId = rrc_objectId;
#endif
#ifdef RRC_AGE
    rrc_outAge = l.hit ? min(l.age + 1u, 65535u) : 0u;
#endif
#ifdef RRC_STATS
    rrc_outOutcome = l.outcome;
#endif
}

#endif
