// Procedural marble and wood (Perlin 1985 style) from RRC_DEMO_OCTAVES octaves of 3D gradient
// noise: the expensive pixel shader of the demos, like the chapter's 215-instruction Perlin
// shader. The octave count is a compile-time #define (default 5) so the loops unroll.
#ifndef RRC_DEMO_MARBLE_GLSL
#define RRC_DEMO_MARBLE_GLSL
#include "noise.glsl"

#ifndef RRC_DEMO_OCTAVES
#define RRC_DEMO_OCTAVES 5
#endif

// Offset between octaves so that their lattices (and zeros at integer points) do not line up.
const vec3 demo_octaveShift = vec3(19.19, 7.37, 3.71);

// Fractional Brownian motion: sum of 0.5^i * noise(2^i p), in about [-1, 1].
float demo_fbm(vec3 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int i = 0; i < RRC_DEMO_OCTAVES; ++i) {
        sum += amplitude * demo_perlin(p);
        p = p * 2.0 + demo_octaveShift;
        amplitude *= 0.5;
    }
    return sum;
}

// Turbulence: sum of 0.5^i * |noise(2^i p)|, in about [0, 1].
float demo_turbulence(vec3 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int i = 0; i < RRC_DEMO_OCTAVES; ++i) {
        sum += amplitude * abs(demo_perlin(p));
        p = p * 2.0 + demo_octaveShift;
        amplitude *= 0.5;
    }
    return sum;
}

// White marble with grey-green veins; about one vein per unit along x.
vec3 demo_marble(vec3 p) {
    float t = 0.5 + 0.5 * sin(3.14159265 * p.x + 6.0 * demo_turbulence(p));
    float vein = pow(t, 0.35);
    return mix(vec3(0.20, 0.24, 0.22), vec3(0.93, 0.92, 0.88), vein);
}

// Wood: rings around the y axis (about 4 per unit of radius) bent by fBm, plus fine grain.
vec3 demo_wood(vec3 p) {
    float n = demo_fbm(p * vec3(1.0, 0.25, 1.0));
    float r = 4.0 * length(p.xz) + 2.5 * n;
    float ring = smoothstep(0.0, 0.45, fract(r)) * (1.0 - smoothstep(0.55, 1.0, fract(r)));
    vec3 light = vec3(0.78, 0.58, 0.36), dark = vec3(0.45, 0.27, 0.13);
    return mix(dark, light, ring) * (0.92 + 0.08 * n);
}

#endif
