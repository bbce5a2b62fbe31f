// The benchmark's expensive pixel shader: improved Perlin noise (Perlin 2002) with the
// permutation table read from a texture, the GPU formulation of the chapter's era (14 integer
// texel fetches per octave), summed over BENCH_OCTAVES octaves into marble. At 5 octaves it costs
// ~30 ms per 1024x768 frame on llvmpipe, as the platform probe's 5-octave Perlin did.
#ifndef BENCH_PERLIN_GLSL
#define BENCH_PERLIN_GLSL
layout(binding = 5) uniform usampler2D bench_permutation;   // 512x1 R8UI: a permutation of 0..255, twice

int bench_perm(int i) { return int(texelFetch(bench_permutation, ivec2(i & 511, 0), 0).r); }

vec3 bench_fade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float bench_grad(int hash, vec3 p) {
    int h = hash & 15;
    float u = h < 8 ? p.x : p.y;
    float v = h < 4 ? p.y : (h == 12 || h == 14 ? p.x : p.z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

float bench_perlin(vec3 p) {
    ivec3 i = ivec3(floor(p)) & 255;
    vec3 f = fract(p);
    vec3 w = bench_fade(f);
    int A = bench_perm(i.x) + i.y, AA = bench_perm(A) + i.z, AB = bench_perm(A + 1) + i.z;
    int B = bench_perm(i.x + 1) + i.y, BA = bench_perm(B) + i.z, BB = bench_perm(B + 1) + i.z;
    return mix(mix(mix(bench_grad(bench_perm(AA), f), bench_grad(bench_perm(BA), f - vec3(1, 0, 0)), w.x),
                   mix(bench_grad(bench_perm(AB), f - vec3(0, 1, 0)), bench_grad(bench_perm(BB), f - vec3(1, 1, 0)), w.x), w.y),
               mix(mix(bench_grad(bench_perm(AA + 1), f - vec3(0, 0, 1)), bench_grad(bench_perm(BA + 1), f - vec3(1, 0, 1)), w.x),
                   mix(bench_grad(bench_perm(AB + 1), f - vec3(0, 1, 1)), bench_grad(bench_perm(BB + 1), f - vec3(1, 1, 1)), w.x), w.y), w.z);
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
