#version 450 core
// Counts the outcome target per category. Each invocation counts a 4x4 block into bins 8-bit
// counters, so the shared atomics are few; one global atomic per category per workgroup.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform usampler2D u_outcomes;
layout(std430, binding = 0) buffer Counts { uint counts[8]; };
shared uint s_counts[8];

void main() {
    uint index = gl_LocalInvocationIndex;
    if (index < 8u) s_counts[index] = 0u;
    barrier();
    ivec2 size = textureSize(u_outcomes, 0);
    ivec2 base = ivec2(gl_GlobalInvocationID.xy) * 4;
    uvec2 bins = uvec2(0u);   // 8 categories x 8 bits; at most 16 per category
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            ivec2 p = base + ivec2(x, y);
            if (p.x < size.x && p.y < size.y) {
                uint o = min(texelFetch(u_outcomes, p, 0).r, 7u);
                if (o < 4u) bins.x += 1u << (o * 8u); else bins.y += 1u << ((o - 4u) * 8u);
            }
        }
    for (uint c = 0u; c < 8u; ++c) {
        uint n = ((c < 4u ? bins.x : bins.y) >> ((c & 3u) * 8u)) & 0xffu;
        if (n != 0u) atomicAdd(s_counts[c], n);
    }
    barrier();
    if (index < 8u && s_counts[index] != 0u) atomicAdd(counts[index], s_counts[index]);
}
