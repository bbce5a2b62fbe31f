// Perspective projections in the two depth conventions the cache understands, and the inverse:
// near and far recovered from a projection matrix (the cache linearises cached depth with them).
#pragma once
#include <glm/mat4x4.hpp>

#include <limits>
#include <optional>

namespace rrc {

inline constexpr double kInfiniteFar = std::numeric_limits<double>::infinity();

// Reversed-Z for glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): depth 1 at `near`, 0 at `far`
// (or at infinity). Clear depth to 0 and test with GL_GREATER.
glm::dmat4 perspectiveReversedZ(double fovyRadians, double aspect, double near, double far = kInfiniteFar);
// The classic OpenGL [-1,1] perspective (glm::perspective), far may be infinite.
glm::dmat4 perspectiveStandard(double fovyRadians, double aspect, double near, double far);

struct DepthRange {
    double near = 0;
    double far = 0;   // kInfiniteFar for an infinite far plane
};

// Near and far of a perspective projection of either convention; nullopt when the matrix is not
// a finite perspective projection of that convention.
std::optional<DepthRange> depthRangeOf(const glm::dmat4& projection, bool reversedZ);

} // namespace rrc
