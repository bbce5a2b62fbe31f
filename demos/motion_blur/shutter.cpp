#include "shutter.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

namespace rrc::motion_blur {
namespace {
// Down the procedural colonnade (demos/support/procedural.hpp): on the stylobate (top y = 0.8),
// 2.5 m inside the right-hand row of columns (x = 5).
glm::dvec3 runnerPosition(const Shot& shot, double t) { return {2.5, 0.8, 20.0 - shot.speed * t}; }
} // namespace

double sampleTime(const Shot& shot, double frameTime, int i, int n) {
    return frameTime + shot.shutter * (double(i) + 0.5) / double(n);
}

glm::dmat4 characterPlacement(const Shot& shot, double t) {
    // The character faces +z; turn it round to run towards -z.
    return glm::rotate(glm::translate(glm::dmat4(1.0), runnerPosition(shot, t)), std::numbers::pi, glm::dvec3(0, 1, 0));
}

glm::dmat4 cameraView(const Shot& shot, double t) {
    const glm::dvec3 runner = runnerPosition(shot, t);
    const glm::dvec3 eye = runner + glm::dvec3(-1.7 + 0.4 * std::sin(3.0 * t), 1.0, 3.4);
    return glm::lookAt(eye, runner + glm::dvec3(0.4, 0.9, -1.5), glm::dvec3(0, 1, 0));
}

} // namespace rrc::motion_blur
