#version 450 core
// One program per pass and variant (the expensive shading is support/shaders/perlin.glsl's marble,
// lit by one directional light; no view-dependent term, so a cached colour is valid from any view):
//   BRUTE          full shading, no cache
//   (no pass)      ControlFlow::OnePass: lookup, then branch between reuse and shading
//   PASS_LOOKUP    hit: the previous sample's colour; miss: discard (left to the miss pass)
//   PASS_MISS      full shading into the cache
#include <support/shaders/perlin.glsl>
#ifndef BRUTE
#include <rrc/lookup.frag>
#endif
in vec3 v_pattern;
in vec3 v_normal;
uniform vec4 u_baseColor;
layout(location = 0) out vec4 o_color;
const vec3 kLight = normalize(vec3(0.45, 0.8, 0.35));

vec4 shade() {
    vec3 n = normalize(v_normal);
    vec3 albedo = demo_marble(v_pattern) * u_baseColor.rgb;
    return vec4(albedo * (0.25 + 0.75 * max(dot(n, kLight), 0.0)), 1.0);
}

void main() {
#if defined(BRUTE)
    o_color = shade();
#elif defined(PASS_LOOKUP)
    rrc_Lookup l = rrc_lookup(false);
    if (!l.hit) discard;
    o_color = rrc_fetchPayload0(l);
    rrc_writeCache(l);
#elif defined(PASS_MISS)
    o_color = shade();
    rrc_writeCache(rrc_lookup(false));   // the outcome, for the statistics
#else
    rrc_Lookup l = rrc_lookup(false);
    o_color = l.hit ? rrc_fetchPayload0(l) : shade();
    rrc_writeCache(l);
#endif
}
