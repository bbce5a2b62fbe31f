#version 450 core
// Every variant's last pass: the sphere's colour where it was drawn, the environment (one
// lookup per pixel) behind it; into RGBA8.
layout(binding = 0) uniform sampler2D u_color;
layout(binding = 1) uniform sampler2D u_depth;    // reversed-Z: 0 where nothing was drawn
layout(binding = 2) uniform samplerCube u_environment;
uniform mat4 u_inverseViewProjection;
in vec2 demo_uv;
layout(location = 0) out vec4 o_color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (texelFetch(u_depth, p, 0).r > 0.0) {
        o_color = vec4(texelFetch(u_color, p, 0).rgb, 1.0);
        return;
    }
    vec4 far = u_inverseViewProjection * vec4(demo_uv * 2.0 - 1.0, 1e-6, 1.0);
    vec4 near = u_inverseViewProjection * vec4(demo_uv * 2.0 - 1.0, 1.0, 1.0);
    o_color = vec4(textureLod(u_environment, far.xyz / far.w - near.xyz / near.w, 0.0).rgb, 1.0);
}
