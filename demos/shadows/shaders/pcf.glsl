// Percentage-closer filtering (Reeves et al. 1987) with k Poisson-disk taps, each a bilinear
// hardware comparison, the whole pattern rotated by a random angle per pixel and frame so that
// frames are independent estimates of the same filtered visibility (chapter section 6.5.5).
// The taps' squared radii are shifted by a random amount too (modulo 1, which preserves area):
// each tap is then uniform over the disk, so every k estimates the same disk average as the
// 256-tap reference instead of a k-ring filter of its own; the pattern keeps its stratification.
// Depth is compared on the receiver plane (its light-space depth gradient from screen
// derivatives), so wide filters on tilted receivers do not shadow themselves.
#include <rrc/hash.glsl>
layout(binding = 4) uniform sampler2DShadow shadow_map;   // compare mode LEQUAL: 1 = lit
uniform mat4 u_lightMatrix;      // world -> shadow map [0,1]^3
uniform int u_taps;              // k
uniform vec2 u_disk[256];        // Poisson taps in the unit disk
uniform float u_radius;          // filter radius in shadow-map uv
uniform float u_bias;            // depth bias against self-shadowing (uv depth units)
uniform uvec2 u_frameSeed;       // frame number, --seed: the rotation comes from these, not time

// Two independent uniforms in [0, 1) for this pixel and frame.
vec2 shadow_random() {
    uint h = rrc_hash(uvec3(uvec2(gl_FragCoord.xy), u_frameSeed.x * 0x9e3779b9u ^ u_frameSeed.y));
    return vec2(rrc_hashToUnit(h), rrc_hashToUnit(rrc_hash(uvec3(h, 0x51edu, u_frameSeed.y))));
}

float shadow_pcf(vec3 world) {
    vec4 l = u_lightMatrix * vec4(world, 1.0);
    vec3 p = l.xyz / l.w;
    // Receiver plane: dz/du, dz/dv from the screen derivatives (clamped where they degenerate).
    vec3 dx = dFdx(p), dy = dFdy(p);
    float det = dx.x * dy.y - dx.y * dy.x;
    vec2 gradient = abs(det) > 1e-12 ? vec2(dx.z * dy.y - dx.y * dy.z, dx.x * dy.z - dx.z * dy.x) / det : vec2(0.0);
    gradient = clamp(gradient, vec2(-4.0), vec2(4.0));
    vec2 r = shadow_random();
    float a = 6.28318531 * r.x;
    mat2 rotation = mat2(cos(a), sin(a), -sin(a), cos(a));
    float lit = 0.0;
    for (int i = 0; i < u_taps; ++i) {
        vec2 t = u_disk[i];
        float r2 = dot(t, t);
        vec2 offset = rotation * (t * (sqrt(fract(r2 + r.y)) * inversesqrt(max(r2, 1e-12)))) * u_radius;
        lit += texture(shadow_map, vec3(p.xy + offset, p.z + dot(gradient, offset) - u_bias));
    }
    return lit / float(u_taps);
}
