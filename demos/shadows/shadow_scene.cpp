#include "shadow_scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace rrc::shadows {

glm::dvec3 sunDirection() { return glm::normalize(glm::dvec3(0.55, 1.0, 0.3)); }

glm::dmat4 casterModel(double t) {
    const glm::dvec3 at(11.3 + 1.5 * std::sin(1.3 * t), 1.5, 18.0 * std::sin(0.35 * t));
    return glm::rotate(glm::translate(glm::dmat4(1.0), at), 0.7 * t, glm::dvec3(0, 1, 0));
}

demo::FlyPath cameraPath(const demo::Bounds& bounds) { return demo::FlyPath::colonnade(bounds); }

} // namespace rrc::shadows
