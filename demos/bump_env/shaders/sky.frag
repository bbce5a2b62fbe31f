#version 450 core
// The environment behind the sphere (one lookup per pixel), drawn where nothing else was.
layout(binding = 2) uniform samplerCube u_environment;
uniform mat4 u_inverseViewProjection;
in vec2 demo_uv;
layout(location = 0) out vec4 o_color;
void main() {
    vec4 far = u_inverseViewProjection * vec4(demo_uv * 2.0 - 1.0, 1e-6, 1.0);
    vec4 near = u_inverseViewProjection * vec4(demo_uv * 2.0 - 1.0, 1.0, 1.0);
    o_color = vec4(textureLod(u_environment, far.xyz / far.w - near.xyz / near.w, 0.0).rgb, 1.0);
}
