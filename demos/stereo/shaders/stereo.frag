#version 450 core
// One program per pass and variant:
//   BRUTE                        full shading, no cache
//   (no pass define)             one pass: lookup and branch (ControlFlow::OnePass)
//   PASS_MISS                    full shading into the cache (right eye, and left-eye misses)
//   PASS_LOOKUP                  left eye hit: copy the right eye's colour (view-independent)
//   PASS_LOOKUP VIEW_DEPENDENT   left eye hit: cached view-independent part + this eye's specular;
//                                saturated highlights are forced misses (chapter section 6.5.1)
// Payloads: 0 = final colour; with VIEW_DEPENDENT 1 = view-independent part (RGBA16F).
#include "shade.glsl"
#ifndef BRUTE
#include <rrc/lookup.frag>
#endif
layout(location = 0) out vec4 o_color;
#if defined(VIEW_DEPENDENT) && !defined(BRUTE)
layout(location = 1) out vec4 o_viewIndependent;
#endif
#ifdef BRUTE
layout(location = 1) out float o_specular;   // where the reference has highlights (error mask)
#endif

void main() {
#if defined(BRUTE)
    vec3 s = specular();
    o_color = vec4(viewIndependent() + s, 1.0);
    o_specular = max(s.r, max(s.g, s.b));
#elif defined(PASS_LOOKUP) && defined(VIEW_DEPENDENT)
    vec3 s = specular();
    rrc_Lookup l = rrc_lookup(false);
    vec3 vi = rrc_fetchPayload1(l).rgb;
    // A highlight that saturates cannot be rebuilt from a clamped cache: recompute it.
    if (!l.hit || any(greaterThan(vi + s, vec3(1.0)))) discard;
    o_color = vec4(vi + s, 1.0);
    o_viewIndependent = vec4(vi, 1.0);
    rrc_writeCache(l);
#elif defined(PASS_LOOKUP)
    rrc_Lookup l = rrc_lookup(false);
    if (!l.hit) discard;
    o_color = rrc_fetchPayload0(l);
    rrc_writeCache(l);
#elif !defined(PASS_MISS) && defined(VIEW_DEPENDENT)
    // One pass, branching: reuse the view-independent part unless missed or saturated.
    vec3 s = specular();
    rrc_Lookup l = rrc_lookup(false);
    vec3 vi = l.hit ? rrc_fetchPayload1(l).rgb : vec3(0.0);
    if (l.hit && any(greaterThan(vi + s, vec3(1.0)))) { l.hit = false; l.outcome = RRC_FORCED; }
    if (!l.hit) vi = viewIndependent();
    o_color = vec4(vi + s, 1.0);
    o_viewIndependent = vec4(vi, 1.0);
    rrc_writeCache(l);
#elif !defined(PASS_MISS)
    // One pass, branching.
    rrc_Lookup l = rrc_lookup(false);
    o_color = l.hit ? rrc_fetchPayload0(l) : vec4(viewIndependent() + specular(), 1.0);
    rrc_writeCache(l);
#else
    vec3 vi = viewIndependent(), s = specular();
    o_color = vec4(vi + s, 1.0);
#ifdef VIEW_DEPENDENT
    o_viewIndependent = vec4(vi, 1.0);
    // Forced (saturated) or ordinary miss: recompute the outcome for the statistics.
    rrc_Lookup l = rrc_lookup(any(greaterThan(vi + s, vec3(1.0))));
#else
    rrc_Lookup l = rrc_lookup(false);
#endif
    rrc_writeCache(l);
#endif
}
