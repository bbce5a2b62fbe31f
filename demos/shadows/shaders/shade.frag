#version 450 core
// Shading for every shadow variant; outputs visibility (0) and colour (1):
//   (none)        PCF with k rotated taps
//   AMORTIZED     plus the cache: a hit blends the fresh PCF value into the reprojected one with
//                 the recursive filter (rrc_blend, age-aware, lambda from the cache block); a miss
//                 starts from the fresh value. Every pixel is shaded, so hit and miss share one
//                 path (no divergent branch): only the blend depends on the lookup.
//   PASS_LOOKUP   (two-pass flow) misses discard and are left to the PASS_MISS program
//   DEFERRED      colour output holds albedo and N.L for the composite pass (blur, remap, threshold)
//   RRC_DEPTH_IN_PAYLOAD  (from the cache) the visibility payload also stores linear depth in g
#include "pcf.glsl"
#ifdef AMORTIZED
#include <rrc/lookup.frag>
#include <rrc/blend.glsl>
#endif
in vec3 v_world;
in vec3 v_normal;
uniform vec4 u_baseColor;
uniform vec3 u_toLight;          // unit vector towards the (directional) light
layout(location = 0) out vec4 o_visibility;
layout(location = 1) out vec4 o_color;

const vec3 kAmbient = vec3(0.25, 0.27, 0.32), kLight = vec3(1.0, 0.95, 0.85);

void main() {
    vec3 n = normalize(v_normal);
    float nDotL = max(dot(n, u_toLight), 0.0);
    // Back faces are dark anyway; PCF runs everywhere so its derivatives see whole quads.
    float visibility = shadow_pcf(v_world);
#ifdef AMORTIZED
    rrc_Lookup l = rrc_lookup(false);
#ifdef PASS_LOOKUP
    if (!l.hit) discard;
#endif
#ifdef RRC_AGE
    uint age = l.age;
#else
    uint age = 65535u;   // no age target: the chapter's plain recursive filter
#endif
    if (l.hit) visibility = rrc_blend(vec4(rrc_fetchPayload0(l).r), vec4(visibility), age, rrc_tolerance.w).r;
    visibility = rrc_storeAmortized(vec4(visibility)).r;
    rrc_writeCache(l);
#endif
#if defined(AMORTIZED) && defined(RRC_DEPTH_IN_PAYLOAD)
    o_visibility = vec4(visibility, rrc_currentLinearDepth(), 0.0, 0.0);   // depth: next frame's lookup
#else
    o_visibility = vec4(visibility);
#endif
#ifdef DEFERRED
    o_color = vec4(u_baseColor.rgb, nDotL);
#else
    o_color = vec4(u_baseColor.rgb * (kAmbient + kLight * nDotL * visibility), 1.0);
#endif
}
