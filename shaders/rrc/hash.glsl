// A 32-bit integer hash (lowbias32 finaliser over a linear mix of three words). The C++ mirror
// is rrc::hash3 in src/refresh.cpp: both must stay bit-identical.
#ifndef RRC_HASH_GLSL
#define RRC_HASH_GLSL

uint rrc_hash(uvec3 v) {
    uint h = v.x * 0x8da6b343u ^ v.y * 0xd8163841u ^ v.z * 0xcb1ab31fu;
    h ^= h >> 16; h *= 0x7feb352du;
    h ^= h >> 15; h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

// Uniform in [0, 1) with 24 bits, exactly representable (same on the CPU).
float rrc_hashToUnit(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }

#endif
