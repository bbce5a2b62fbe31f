// Improved 3D Perlin gradient noise (hash-based gradients, no textures) and fBm. The benchmark's
// "expensive pixel shader": at 5 octaves about the cost of the chapter's 215-instruction shader.
#ifndef BENCH_PERLIN_GLSL
#define BENCH_PERLIN_GLSL
#include <rrc/hash.glsl>

vec3 bench_fade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float bench_grad(ivec3 cell, vec3 offset) {
    uint h = rrc_hash(uvec3(cell)) & 15u;
    // The 12 edge directions of a cube (4 repeated), as in improved noise.
    float u = h < 8u ? offset.x : offset.y;
    float v = h < 4u ? offset.y : (h == 12u || h == 14u ? offset.x : offset.z);
    return ((h & 1u) == 0u ? u : -u) + ((h & 2u) == 0u ? v : -v);
}

float bench_perlin(vec3 p) {
    ivec3 i = ivec3(floor(p));
    vec3 f = fract(p);
    vec3 w = bench_fade(f);
    float n000 = bench_grad(i, f), n100 = bench_grad(i + ivec3(1, 0, 0), f - vec3(1, 0, 0));
    float n010 = bench_grad(i + ivec3(0, 1, 0), f - vec3(0, 1, 0)), n110 = bench_grad(i + ivec3(1, 1, 0), f - vec3(1, 1, 0));
    float n001 = bench_grad(i + ivec3(0, 0, 1), f - vec3(0, 0, 1)), n101 = bench_grad(i + ivec3(1, 0, 1), f - vec3(1, 0, 1));
    float n011 = bench_grad(i + ivec3(0, 1, 1), f - vec3(0, 1, 1)), n111 = bench_grad(i + ivec3(1, 1, 1), f - vec3(1, 1, 1));
    return mix(mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y),
               mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y), w.z);
}

#ifndef BENCH_OCTAVES
#define BENCH_OCTAVES 5
#endif

vec3 bench_marble(vec3 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int o = 0; o < BENCH_OCTAVES; ++o) {
        sum += amplitude * abs(bench_perlin(p));
        p *= 2.03;
        amplitude *= 0.5;
    }
    float veins = 0.5 + 0.5 * sin(p.x * 0.15 + 8.0 * sum);
    return mix(vec3(0.25, 0.22, 0.2), vec3(0.95, 0.93, 0.9), veins);
}

#endif
