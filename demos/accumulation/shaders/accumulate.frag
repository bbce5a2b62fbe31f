#version 450 core
// Adds one sample, weighted, into the float accumulation target (blending ONE, ONE).
layout(binding = 0) uniform sampler2D u_sample;
uniform float u_weight;
out vec4 o_color;
void main() { o_color = texelFetch(u_sample, ivec2(gl_FragCoord.xy), 0) * u_weight; }
