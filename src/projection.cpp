// Projection matrices (column-major, m[column][row]) and near/far recovery.
#include <rrc/projection.hpp>

#include <cmath>

namespace rrc {

glm::dmat4 perspectiveReversedZ(double fovy, double aspect, double near, double far) {
    const double f = 1.0 / std::tan(fovy / 2.0);
    glm::dmat4 m(0.0);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][3] = -1.0;
    // clip.z = A*z_view + B with d = clip.z / clip.w equal to 1 at near and 0 at far.
    const bool infinite = std::isinf(far);
    m[2][2] = infinite ? 0.0 : near / (far - near);
    m[3][2] = infinite ? near : near * far / (far - near);
    return m;
}

glm::dmat4 perspectiveStandard(double fovy, double aspect, double near, double far) {
    const double f = 1.0 / std::tan(fovy / 2.0);
    glm::dmat4 m(0.0);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][3] = -1.0;
    const bool infinite = std::isinf(far);
    m[2][2] = infinite ? -1.0 : -(far + near) / (far - near);
    m[3][2] = infinite ? -2.0 * near : -2.0 * far * near / (far - near);
    return m;
}

std::optional<DepthRange> depthRangeOf(const glm::dmat4& p, bool reversedZ) {
    const double a = p[2][2], b = p[3][2];
    if (p[2][3] != -1.0 || p[3][3] != 0.0 || !std::isfinite(a) || !std::isfinite(b)) return std::nullopt;
    DepthRange r;
    if (reversedZ) {
        if (a == 0.0) { r.near = b; r.far = kInfiniteFar; }
        else { r.far = b / a; r.near = a * r.far / (1.0 + a); }
    } else {
        r.near = b / (a - 1.0);
        r.far = a == -1.0 ? kInfiniteFar : b / (a + 1.0);
    }
    const bool ok = std::isfinite(r.near) && r.near > 0.0 && (std::isinf(r.far) || r.far > r.near);
    return ok ? std::optional(r) : std::nullopt;
}

} // namespace rrc
