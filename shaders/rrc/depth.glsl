// Depth conventions of the cache: linear view depth from window depth, for the standard
// [-1,1] perspective and for reversed-Z with glClipControl(ZERO_TO_ONE). A far plane <= 0 means
// an infinite far plane.
#ifndef RRC_DEPTH_GLSL
#define RRC_DEPTH_GLSL

float rrc_linearDepth(float d, float near, float far, bool reversed) {
    if (reversed) {
        // d = near*(far - z) / (z*(far - near)); with an infinite far plane d = near / z.
        return far > 0.0 ? (near * far) / (near + d * (far - near)) : near / d;
    }
    float ndc = 2.0 * d - 1.0;
    return far > 0.0 ? (2.0 * near * far) / (far + near - ndc * (far - near)) : (2.0 * near) / (1.0 - ndc);
}

#endif
