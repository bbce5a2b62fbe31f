// The benchmark's expensive pixel shader: improved Perlin noise (Perlin 2002) with the
// permutation table read from a texture, the GPU formulation of the chapter's era (14 integer
// texel fetches per octave), summed over DEMO_OCTAVES octaves into marble. At 5 octaves it costs
// ~30 ms per 1024x768 frame on llvmpipe, as the platform probe's 5-octave Perlin did.
#ifndef DEMO_PERLIN_GLSL
#define DEMO_PERLIN_GLSL
layout(binding = 5) uniform usampler2D demo_permutation;   // 512x1 R8UI: a permutation of 0..255, twice

int demo_perm(int i) { return int(texelFetch(demo_permutation, ivec2(i & 511, 0), 0).r); }

vec3 demo_fade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float demo_grad(int hash, vec3 p) {
    int h = hash & 15;
    float u = h < 8 ? p.x : p.y;
    float v = h < 4 ? p.y : (h == 12 || h == 14 ? p.x : p.z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

float demo_perlin(vec3 p) {
    ivec3 i = ivec3(floor(p)) & 255;
    vec3 f = fract(p);
    vec3 w = demo_fade(f);
    int A = demo_perm(i.x) + i.y, AA = demo_perm(A) + i.z, AB = demo_perm(A + 1) + i.z;
    int B = demo_perm(i.x + 1) + i.y, BA = demo_perm(B) + i.z, BB = demo_perm(B + 1) + i.z;
    return mix(mix(mix(demo_grad(demo_perm(AA), f), demo_grad(demo_perm(BA), f - vec3(1, 0, 0)), w.x),
                   mix(demo_grad(demo_perm(AB), f - vec3(0, 1, 0)), demo_grad(demo_perm(BB), f - vec3(1, 1, 0)), w.x), w.y),
               mix(mix(demo_grad(demo_perm(AA + 1), f - vec3(0, 0, 1)), demo_grad(demo_perm(BA + 1), f - vec3(1, 0, 1)), w.x),
                   mix(demo_grad(demo_perm(AB + 1), f - vec3(0, 1, 1)), demo_grad(demo_perm(BB + 1), f - vec3(1, 1, 1)), w.x), w.y), w.z);
}

#ifndef DEMO_OCTAVES
#define DEMO_OCTAVES 5
#endif

vec3 demo_marble(vec3 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int o = 0; o < DEMO_OCTAVES; ++o) {
        sum += amplitude * abs(demo_perlin(p));
        p *= 2.03;
        amplitude *= 0.5;
    }
    float veins = 0.5 + 0.5 * sin(p.x * 0.15 + 8.0 * sum);
    return mix(vec3(0.25, 0.22, 0.2), vec3(0.95, 0.93, 0.9), veins);
}
#endif
