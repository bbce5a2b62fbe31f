#version 450 core
// Outcome target to colours: hits green, misses red, forced misses and refreshes blue, empty
// black, invalid (camera cut) dark red (chapter figures 6.1 and 6.6d).
layout(binding = 0) uniform usampler2D u_outcomes;
out vec4 o_color;
void main() {
    uint o = texelFetch(u_outcomes, ivec2(gl_FragCoord.xy), 0).r;
    const vec3 colours[8] = vec3[8](vec3(0.0), vec3(0.1, 0.8, 0.1), vec3(0.9, 0.1, 0.1), vec3(0.9, 0.1, 0.1),
                                    vec3(0.9, 0.5, 0.1), vec3(0.1, 0.2, 0.9), vec3(0.2, 0.6, 1.0), vec3(0.5, 0.0, 0.0));
    o_color = vec4(colours[min(o, 7u)], 1.0);
}
