#version 450 core
// Environment-mapped bump mapping, supersampled (chapter section 6.5.4): for each of k = n x n
// sub-pixel samples the surface point is extrapolated along the screen derivatives, its
// bump-mapped normal rebuilt, the view vector reflected and the environment looked up; the
// samples are averaged. The n x n grid is shifted toroidally by a random offset per pixel and
// frame, so every sample is uniform over the pixel (unbiased for the box-filtered pixel) and
// the grid stays stratified; with u_jitter = 0 it samples the stratum centres (the reference).
//   AMORTIZED     the average is blended into the reprojected cache entry (recursive filter,
//                 age-aware, lambda from the cache block); misses start from the fresh average
#include <rrc/hash.glsl>
#ifdef AMORTIZED
#include <rrc/lookup.frag>
#include <rrc/blend.glsl>
#endif
layout(binding = 0) uniform sampler2D bump_slopes;   // RG: height slopes per texel (REPEAT)
layout(binding = 1) uniform samplerCube bump_environment;
uniform mat4 u_model;          // rotation + uniform scale + translation
uniform vec3 u_eye;            // world
uniform int u_grid;            // n: k = n * n samples
uniform float u_jitter;        // 1: random shift per pixel and frame, 0: stratum centres
uniform uvec2 u_frameSeed;     // frame number, --seed
uniform vec2 u_tiles;          // bump repetitions around / along the sphere
uniform float u_bumpStrength;
in vec3 v_object;
layout(location = 0) out vec4 o_color;

const float kPi = 3.14159265;

vec3 bump_sample(vec3 p) {
    vec3 n = normalize(p);
    vec2 uv = vec2(atan(n.z, n.x) / (2.0 * kPi) + 0.5, acos(clamp(n.y, -1.0, 1.0)) / kPi);
    vec3 t = normalize(vec3(-n.z, 0.0, n.x) + vec3(1e-6, 0.0, 0.0));   // along +u (longitude)
    vec3 b = cross(n, t);
    vec2 slope = textureLod(bump_slopes, uv * u_tiles, 0.0).rg;
    vec3 bumped = normalize(n - u_bumpStrength * (slope.x * t - slope.y * b));
    vec3 world = (u_model * vec4(p, 1.0)).xyz;
    vec3 normal = normalize(mat3(u_model) * bumped);
    return textureLod(bump_environment, reflect(normalize(world - u_eye), normal), 0.0).rgb;
}

void main() {
    // Derivatives first, in uniform control flow.
    vec3 dx = dFdx(v_object), dy = dFdy(v_object);
    uint h = rrc_hash(uvec3(uvec2(gl_FragCoord.xy), u_frameSeed.x * 0x9e3779b9u ^ u_frameSeed.y));
    vec2 shift = u_jitter * vec2(rrc_hashToUnit(h), rrc_hashToUnit(rrc_hash(uvec3(h, 0x7f4au, u_frameSeed.y))));
    float n = float(u_grid);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < u_grid; ++j)
        for (int i = 0; i < u_grid; ++i) {
            vec2 o = fract((vec2(i, j) + 0.5) / n + shift) - 0.5;
            sum += bump_sample(v_object + dx * o.x + dy * o.y);
        }
    vec4 color = vec4(sum / (n * n), 1.0);
#ifdef AMORTIZED
    rrc_Lookup l = rrc_lookup(false);
#ifdef RRC_AGE
    uint age = l.age;
#else
    uint age = 65535u;   // no age target: the chapter's plain recursive filter
#endif
    if (l.hit) color = rrc_blend(rrc_fetchPayload0(l), color, age, rrc_tolerance.w);
    color = rrc_storeAmortized(color);
    rrc_writeCache(l);
#endif
    o_color = color;
}
