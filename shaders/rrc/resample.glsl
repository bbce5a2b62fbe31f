// Payload resampling at a reprojected (non-integer) position: nearest, bilinear, and bicubic
// Catmull-Rom in 9 bilinear fetches (the two inner taps per axis merged into one bilinear tap,
// which is exact because their weights have the same sign).
#ifndef RRC_RESAMPLE_GLSL
#define RRC_RESAMPLE_GLSL

vec4 rrc_sampleNearest(sampler2D s, vec2 uv) {
    ivec2 size = textureSize(s, 0);
    return texelFetch(s, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0);
}

uvec4 rrc_sampleNearest(usampler2D s, vec2 uv) {
    ivec2 size = textureSize(s, 0);
    return texelFetch(s, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0);
}

vec4 rrc_sampleBilinear(sampler2D s, vec2 uv) { return textureLod(s, uv, 0.0); }

vec4 rrc_sampleBicubic(sampler2D s, vec2 uv) {
    vec2 size = vec2(textureSize(s, 0));
    vec2 pos = uv * size;
    vec2 center1 = floor(pos - 0.5) + 0.5;   // texel centre left of / below the sample
    vec2 f = pos - center1;
    // Catmull-Rom weights of the four taps at center1 - 1, center1, center1 + 1, center1 + 2.
    vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    vec2 w3 = f * f * (-0.5 + 0.5 * f);
    vec2 w12 = w1 + w2;
    vec2 t0 = (center1 - 1.0) / size;
    vec2 t12 = (center1 + w2 / w12) / size;
    vec2 t3 = (center1 + 2.0) / size;
    vec4 r = vec4(0.0);
    r += (textureLod(s, vec2(t0.x, t0.y), 0.0) * w0.x + textureLod(s, vec2(t12.x, t0.y), 0.0) * w12.x +
          textureLod(s, vec2(t3.x, t0.y), 0.0) * w3.x) * w0.y;
    r += (textureLod(s, vec2(t0.x, t12.y), 0.0) * w0.x + textureLod(s, vec2(t12.x, t12.y), 0.0) * w12.x +
          textureLod(s, vec2(t3.x, t12.y), 0.0) * w3.x) * w12.y;
    r += (textureLod(s, vec2(t0.x, t3.y), 0.0) * w0.x + textureLod(s, vec2(t12.x, t3.y), 0.0) * w12.x +
          textureLod(s, vec2(t3.x, t3.y), 0.0) * w3.x) * w3.y;
    return r;
}

#endif
