// Amortized supersampling: the recursive filter C_f = lambda*C_{f-1} + (1 - lambda)*s_f
// (chapter section 6.4.5) with an age-aware weight: while an entry holds few samples the weight
// gives their exact running mean, so a fresh entry is not biased toward its first sample.
// Non-finite values are never written into the cache and never read out of it.
//
// Writing the blend into a payload of limited precision needs rrc_storeAmortized: a plain store
// rounds every frame the same way, so the filter stalls in a dead zone of about
// 0.5 LSB / (1 - lambda) (round to nearest) or 1 ulp / (1 - lambda) (llvmpipe truncates float16
// and R11G11B10F writes): -9.5/255 for RGBA8 at lambda = 0.95 (docs/stability.md).
// rrc_storeAmortized rounds stochastically onto the payload format's own grid with a
// per-pixel, per-frame dither, so the expected stored value is the blended value; the store
// itself is then exact (float formats) or guarded against either rounding mode (UNORM), so the
// result does not depend on how the implementation rounds.
#ifndef RRC_BLEND_GLSL
#define RRC_BLEND_GLSL
#include <rrc/cache_block.glsl>
#include <rrc/hash.glsl>

bool rrc_isFinite(vec4 v) { return !any(isnan(v)) && !any(isinf(v)); }

// `cachedAge` = frames the cached entry survived, so it holds cachedAge + 1 samples.
vec4 rrc_blend(vec4 cached, vec4 fresh, uint cachedAge, float lambda) {
    bool freshOk = rrc_isFinite(fresh), cachedOk = rrc_isFinite(cached);
    if (!freshOk) return cachedOk ? cached : vec4(0.0);
    if (!cachedOk) return fresh;
    float samples = float(cachedAge) + 1.0;
    float weight = min(lambda, samples / (samples + 1.0));
    return mix(fresh, cached, weight);
}

// The sample that starts a new entry (after a miss): finite or zero.
vec4 rrc_firstSample(vec4 fresh) { return rrc_isFinite(fresh) ? fresh : vec4(0.0); }

// Storage of each payload, from rrc::Cache::defines(): RRC_PAYLOADn_QUANT is 0 when stores are
// exact (32-bit float, integer), 1 for UNORM with RRC_PAYLOADn_BITS bits per channel, 2 for small
// floats with RRC_PAYLOADn_BITS mantissa bits per channel (0: channel absent or exact) and
// largest finite value RRC_PAYLOADn_MAX.
#ifndef RRC_PAYLOAD0_QUANT
#define RRC_PAYLOAD0_QUANT 0
#define RRC_PAYLOAD0_BITS ivec4(0)
#define RRC_PAYLOAD0_MAX vec4(0.0)
#endif

// Four independent dither values in (0, 1), 16 bits each, for this pixel and the cache frame.
// `salt` separates independent uses (payloads) in one pixel.
vec4 rrc_ditherNoise(uvec2 pixel, uint salt) {
    uint a = rrc_hash(uvec3(pixel, rrc_frameInfo.x ^ (0x68e31da4u + 2u * salt)));
    uint b = rrc_hash(uvec3(pixel, rrc_frameInfo.x ^ (0x68e31da5u + 2u * salt)));
    uvec4 bits = uvec4(a & 0xffffu, a >> 16, b & 0xffffu, b >> 16);
    return (vec4(bits) + 0.5) * (1.0 / 65536.0);
}

// Rounds `v` onto the grid of a payload format: down with probability 1 - frac, up with
// probability frac, where frac is v's position between its two representable neighbours and
// `u` the dither (uniform in (0, 1)). Non-finite values pass unchanged (rrc_blend rejects them
// on the next read); finite values beyond the format's range clamp to its largest finite value
// instead of turning into infinity on the store.
vec4 rrc_roundStochastic(vec4 v, int kind, ivec4 bits, vec4 maxValue, vec4 u) {
    if (kind == 0) return v;
    bvec4 keep = bvec4(uvec4(isnan(v)) | uvec4(isinf(v)) | uvec4(equal(bits, ivec4(0))));
    vec4 r;
    if (kind == 1) {
        // UNORM: k = floor(v * n + u) is exact in float. (k + g) / n with g = 1 / (2 (n + 1))
        // converts back to k under every conversion seen: round(x n), trunc(x n), and
        // about floor(x (n + 1)) (llvmpipe's GL_RGB10_A2), since k + g + k / n < k + 1 for k < n.
        vec4 n = vec4((ivec4(1) << bits) - 1);
        vec4 k = floor(clamp(v, 0.0, 1.0) * n + u);
        r = min((k + 0.5 / (n + 1.0)) / n, vec4(1.0));
    } else {
        // Float with `bits` mantissa bits and a minimum normal exponent of -14 (half, 11/10-bit):
        // the spacing of representable values around |v| is 2^(exponent - bits); the rounded
        // value has at most bits + 1 significant bits, so the store is exact.
        vec4 a = abs(v);
        ivec4 e;
        frexp(a, e);   // a = m * 2^e, m in [0.5, 1)
        vec4 ulp = ldexp(vec4(1.0), max(e - 1, ivec4(-14)) - bits);
        r = sign(v) * min(floor(a / ulp + u) * ulp, maxValue);
    }
    return mix(r, v, keep);
}

// The value to write into payload 0 (fragment shaders): `v` rounded stochastically for its
// format, so the recursive filter converges to the true mean instead of stalling.
//   o_payload = rrc_storeAmortized(rrc_blend(cached, fresh, age, lambda));
// rrc_storeAmortized1..3 do the same for payloads 1..3.
vec4 rrc_storeAmortized(vec4 v) {
    return rrc_roundStochastic(v, RRC_PAYLOAD0_QUANT, RRC_PAYLOAD0_BITS, RRC_PAYLOAD0_MAX,
                               rrc_ditherNoise(uvec2(gl_FragCoord.xy), 0u));
}
#ifdef RRC_PAYLOAD1_QUANT
vec4 rrc_storeAmortized1(vec4 v) {
    return rrc_roundStochastic(v, RRC_PAYLOAD1_QUANT, RRC_PAYLOAD1_BITS, RRC_PAYLOAD1_MAX,
                               rrc_ditherNoise(uvec2(gl_FragCoord.xy), 1u));
}
#endif
#ifdef RRC_PAYLOAD2_QUANT
vec4 rrc_storeAmortized2(vec4 v) {
    return rrc_roundStochastic(v, RRC_PAYLOAD2_QUANT, RRC_PAYLOAD2_BITS, RRC_PAYLOAD2_MAX,
                               rrc_ditherNoise(uvec2(gl_FragCoord.xy), 2u));
}
#endif
#ifdef RRC_PAYLOAD3_QUANT
vec4 rrc_storeAmortized3(vec4 v) {
    return rrc_roundStochastic(v, RRC_PAYLOAD3_QUANT, RRC_PAYLOAD3_BITS, RRC_PAYLOAD3_MAX,
                               rrc_ditherNoise(uvec2(gl_FragCoord.xy), 3u));
}
#endif

#endif
