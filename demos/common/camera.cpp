// Camera basics (view and projection matrices) and the interactive fly controller. The scripted
// paths live in camera_paths.cpp.
#include "camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace rrc::demo {

glm::dmat4 perspective(double fovyRadians, double aspect, double near, double far) {
    return perspectiveReversedZ(fovyRadians, aspect, near, far);
}

glm::dvec3 Camera::forward() const { return orientation * glm::dvec3(0.0, 0.0, -1.0); }
glm::dvec3 Camera::right() const { return orientation * glm::dvec3(1.0, 0.0, 0.0); }
glm::dvec3 Camera::up() const { return orientation * glm::dvec3(0.0, 1.0, 0.0); }

glm::dmat4 Camera::view() const {
    return glm::mat4_cast(glm::conjugate(orientation)) * glm::translate(glm::dmat4(1.0), -position);
}

glm::dmat4 Camera::projection(double aspect) const { return perspective(fovy, aspect, near, far); }

void Camera::lookAt(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& upHint) {
    position = eye;
    const glm::dvec3 direction = target - eye;
    if (glm::length(direction) <= 0.0) return;   // keep the orientation rather than produce NaNs
    orientation = glm::normalize(glm::quatLookAtRH(glm::normalize(direction), upHint));
}

void FlyController::attach(const Camera& camera) {
    const glm::dvec3 f = camera.forward();
    pitch_ = std::asin(std::clamp(f.y, -1.0, 1.0));
    yaw_ = std::atan2(-f.x, -f.z);
}

bool FlyController::update(Camera& camera, const ControllerInput& in) {
    constexpr double kMaxPitch = 1.5533;   // 89 degrees: keeps yaw well defined
    speed = std::clamp(speed * std::pow(1.2, in.scroll), 0.01, 1000.0);
    bool changed = false;
    if (in.dragging && (in.mouseDelta.x != 0.0 || in.mouseDelta.y != 0.0)) {
        yaw_ -= in.mouseDelta.x * sensitivity;
        pitch_ = std::clamp(pitch_ - in.mouseDelta.y * sensitivity, -kMaxPitch, kMaxPitch);
        camera.orientation = glm::angleAxis(yaw_, glm::dvec3(0.0, 1.0, 0.0)) *
                             glm::angleAxis(pitch_, glm::dvec3(1.0, 0.0, 0.0));
        changed = true;
    }
    glm::dvec3 move(0.0);
    if (in.forward) move += camera.forward();
    if (in.back) move -= camera.forward();
    if (in.right) move += camera.right();
    if (in.left) move -= camera.right();
    if (in.up) move.y += 1.0;
    if (in.down) move.y -= 1.0;
    if (glm::length(move) > 0.0) {
        camera.position += glm::normalize(move) * speed * (in.fast ? 4.0 : 1.0) * in.dt;
        changed = true;
    }
    return changed;
}

} // namespace rrc::demo
