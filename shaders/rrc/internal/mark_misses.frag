#version 450 core
// Two-pass flow, between the lookup and the miss pass: a full-screen triangle over the pixels the
// prepass covered (stencil 1) that lets through those whose outcome is not a hit, so the stencil
// op marks them (2) for the miss pass and ANY_SAMPLES_PASSED counts them. The lookup pass itself
// writes no stencil, so its discards leave llvmpipe's (and any GPU's) early depth test on.
layout(binding = 0) uniform usampler2D rrc_outcomes;
void main() {
    if (texelFetch(rrc_outcomes, ivec2(gl_FragCoord.xy), 0).r == 1u) discard;   // RRC_HIT
}
