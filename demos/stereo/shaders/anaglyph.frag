#version 450 core
// Red from the left eye, green and blue from the right (chapter section 6.5.1).
layout(binding = 0) uniform sampler2D u_left;
layout(binding = 1) uniform sampler2D u_right;
out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    o_color = vec4(texelFetch(u_left, p, 0).r, texelFetch(u_right, p, 0).gb, 1.0);
}
