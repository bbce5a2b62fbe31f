// Amortized supersampling: the recursive filter C_f = lambda*C_{f-1} + (1 - lambda)*s_f
// (chapter section 6.4.5) with an age-aware weight: while an entry holds few samples the weight
// gives their exact running mean, so a fresh entry is not biased toward its first sample.
// Non-finite values are never written into the cache and never read out of it.
#ifndef RRC_BLEND_GLSL
#define RRC_BLEND_GLSL

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

#endif
