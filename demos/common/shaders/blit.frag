#version 450 core
// Texture to viewport (with common/shaders/fullscreen.vert): colour times demo_scale, or one
// channel as grey when demo_channel >= 0. Used to show a demo's output in the window.
in vec2 demo_uv;
layout(binding = 0) uniform sampler2D demo_source;
layout(location = 0) uniform float demo_scale;
layout(location = 1) uniform int demo_channel;
layout(location = 0) out vec4 demo_color;

void main() {
    vec4 c = texture(demo_source, demo_uv);
    demo_color = demo_channel >= 0 ? vec4(vec3(c[demo_channel]), 1.0) : vec4(c.rgb * demo_scale, 1.0);
}
