// 3D gradient noise after Perlin's "Improving Noise" (2002): quintic fade, the 12 cube-edge
// gradients chosen by 4 hash bits. The permutation table is replaced by an integer hash, so no
// texture is needed and every GL implementation gives the same field; RRC_DEMO_NOISE_SEED (a uint)
// selects another field. Four lattice corners are hashed and graded at once in vec4 arithmetic.
#ifndef RRC_DEMO_NOISE_GLSL
#define RRC_DEMO_NOISE_GLSL

#ifndef RRC_DEMO_NOISE_SEED
#define RRC_DEMO_NOISE_SEED 0u
#endif

// Two multiply-xorshift rounds of the lowbias32 finaliser over a linear mix of the coordinates.
uvec4 demo_hash4(uvec4 x, uvec4 y, uvec4 z) {
    uvec4 h = (x * 0x8da6b343u) ^ (y * 0xd8163841u) ^ (z * 0xcb1ab31fu) ^ uvec4(uint(RRC_DEMO_NOISE_SEED) * 0x9e3779b9u);
    h ^= h >> 16u; h *= 0x7feb352du;
    h ^= h >> 15u; h *= 0x846ca68bu;
    return h ^ (h >> 16u);
}

// Perlin's grad(): dot of the corner offset (x, y, z) with gradient h & 15, four corners at once.
vec4 demo_grad4(uvec4 h, vec4 x, vec4 y, vec4 z) {
    h &= 15u;
    vec4 u = mix(y, x, lessThan(h, uvec4(8u)));
    vec4 v = mix(mix(z, x, equal(h | 2u, uvec4(14u))), y, lessThan(h, uvec4(4u)));
    return u * (1.0 - 2.0 * vec4(h & 1u)) + v * (1.0 - vec4(h & 2u));
}

vec3 demo_fade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// Gradient noise in about [-1, 1], zero at every lattice point.
float demo_perlin(vec3 p) {
    vec3 i = floor(p);
    vec3 f = p - i;
    uvec3 c = uvec3(ivec3(i));
    vec3 w = demo_fade(f);
    uvec4 cx = c.x + uvec4(0u, 1u, 0u, 1u);
    uvec4 cy = c.y + uvec4(0u, 0u, 1u, 1u);
    vec4 fx = f.x - vec4(0.0, 1.0, 0.0, 1.0);
    vec4 fy = f.y - vec4(0.0, 0.0, 1.0, 1.0);
    vec4 g0 = demo_grad4(demo_hash4(cx, cy, uvec4(c.z)), fx, fy, vec4(f.z));
    vec4 g1 = demo_grad4(demo_hash4(cx, cy, uvec4(c.z + 1u)), fx, fy, vec4(f.z - 1.0));
    vec4 g = mix(g0, g1, w.z);            // corners x0y0, x1y0, x0y1, x1y1
    vec2 gy = mix(g.xy, g.zw, w.y);
    return mix(gy.x, gy.y, w.x);
}

#endif
