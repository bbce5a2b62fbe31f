#version 450 core
// Brute force (BRUTE), or the cached variants: one-pass branch, two-pass lookup (PASS_LOOKUP)
// and miss (PASS_MISS). MISS_FRACTION of the pixels are forced to miss, in 8x8 blocks
// (CLUSTERED) or pixel by pixel.
#include <support/shaders/perlin.glsl>
#include <rrc/hash.glsl>
#ifndef BRUTE
#include <rrc/lookup.frag>
#endif
in vec3 v_world;
layout(location = 0) out vec4 o_color;
uniform float u_missFraction;
uniform uint u_clustered;

vec4 shade() {
#ifdef RRC_DEPTH_IN_PAYLOAD
    return vec4(demo_marble(v_world * 2.0), 1.0 / gl_FragCoord.w);
#else
    return vec4(demo_marble(v_world * 2.0), 1.0);
#endif
}

bool forcedMiss() {
    uvec2 cell = u_clustered != 0u ? uvec2(gl_FragCoord.xy) / 8u : uvec2(gl_FragCoord.xy);
    return rrc_hashToUnit(rrc_hash(uvec3(cell, 99u))) < u_missFraction;
}

void main() {
#ifdef BRUTE
    o_color = shade();
#else
    rrc_Lookup l = rrc_lookup(forcedMiss());
#if defined(PASS_LOOKUP)
    if (!l.hit) discard;
    o_color = rrc_fetchPayload0(l);
#elif defined(PASS_MISS)
    o_color = shade();
#else
    o_color = l.hit ? rrc_fetchPayload0(l) : shade();
#endif
    rrc_writeCache(l);
#endif
}
