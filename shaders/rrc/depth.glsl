// Depth conventions shared by the cache snippets: view-space linear depth from window depth for
// the standard [-1,1] and the reversed-Z [0,1] (glClipControl ZERO_TO_ONE) perspective.
#ifndef RRC_DEPTH_GLSL
#define RRC_DEPTH_GLSL

// Positive distance along the view axis for window depth `d` of a perspective projection with
// planes near/far. `reversed` selects reversed-Z with ZERO_TO_ONE clip control (far may be inf).
float rrc_linearDepth(float d, float near, float far, bool reversed) {
    if (reversed) {
        // d = near*(far - z) / (z*(far - near)); with an infinite far plane d = near / z.
        return isinf(far) ? near / max(d, 1e-30) : (near * far) / (near + d * (far - near));
    }
    float ndc = 2.0 * d - 1.0;
    return (2.0 * near * far) / (far + near - ndc * (far - near));
}

#endif
