// What rrc-shadows and its benchmark share: the sun, the caster's motion and the camera path
// over the temple, all functions of the fixed clock so headless runs are deterministic.
#pragma once
#include "../common/camera.hpp"

#include <glm/mat4x4.hpp>

namespace rrc::shadows {

// Towards the sun: high and to the side, so the columns cast across the aisles.
glm::dvec3 sunDirection();
// The caster walks up and down the +x aisle of the temple (stylobate top at y = 1.5).
glm::dmat4 casterModel(double t);
// The fly-through down the colonnade (the stereo demo's path).
demo::FlyPath cameraPath(const demo::Bounds& bounds);

} // namespace rrc::shadows
