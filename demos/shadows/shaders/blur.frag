#version 450 core
// Depth-aware screen-space blur of the visibility (chapter fig. 6.9e; weights as the bilateral
// filter of the spatiotemporal framework excerpt): a 5x5 Gaussian whose taps lose weight with
// their relative difference in linear depth, so shadows do not bleed across silhouettes.
layout(binding = 0) uniform sampler2D u_visibility;
layout(binding = 1) uniform sampler2D u_depth;     // reversed-Z, infinite far: linear = near / d
uniform float u_near;
uniform float u_depthSigma;                        // relative depth difference that halves ~the weight
in vec2 demo_uv;
layout(location = 0) out vec4 o_visibility;

float linearDepth(ivec2 p) { return u_near / max(texelFetch(u_depth, p, 0).r, 1e-30); }

void main() {
    ivec2 c = ivec2(gl_FragCoord.xy), size = textureSize(u_visibility, 0) - 1;
    float zc = linearDepth(c), sum = 0.0, weights = 0.0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            ivec2 p = clamp(c + ivec2(x, y), ivec2(0), size);
            float dz = (linearDepth(p) - zc) / (zc * u_depthSigma);
            float w = exp(-0.5 * float(x * x + y * y) - dz * dz);
            sum += w * texelFetch(u_visibility, p, 0).r;
            weights += w;
        }
    // Channel g passes through: the cache's linear depth when it shares the payload.
    o_visibility = vec4(sum / weights, texelFetch(u_visibility, c, 0).g, 0.0, 0.0);
}
