#version 450 core
// Final colour from visibility and the deferred albedo / N.L, with the options of chapter
// fig. 6.9: a smoothstep remap narrows the PCF transitions, a threshold turns the (denoised)
// visibility into an approximate alias-free hard shadow. Sky where nothing was drawn.
layout(binding = 0) uniform sampler2D u_visibility;
layout(binding = 1) uniform sampler2D u_albedo;    // rgb albedo, a = N.L; alpha 0 and black: sky
uniform int u_remap;                               // 0 off, 1 smoothstep, 2 threshold
in vec2 demo_uv;
layout(location = 0) out vec4 o_color;

const vec3 kAmbient = vec3(0.25, 0.27, 0.32), kLight = vec3(1.0, 0.95, 0.85);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float v = texelFetch(u_visibility, p, 0).r;
    vec4 g = texelFetch(u_albedo, p, 0);
    if (u_remap == 1) v = smoothstep(0.3, 0.7, v);
    if (u_remap == 2) v = step(0.5, v);
    o_color = vec4(g.rgb * (kAmbient + kLight * g.a * v), 1.0);
}
