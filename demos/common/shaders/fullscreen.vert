#version 450 core
// One triangle that covers the viewport: vertices (-1,-1), (3,-1), (-1,3) from gl_VertexID.
// demo_uv is (0,0) at the lower-left corner of the viewport and (1,1) at the upper-right.
out vec2 demo_uv;

void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    demo_uv = 0.5 * p + 0.5;
    gl_Position = vec4(p, 0.0, 1.0);
}
