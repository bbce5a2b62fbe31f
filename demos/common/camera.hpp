// The demos' camera: double-precision position and orientation, a reversed-Z perspective for
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), deterministic scripted paths (fly-through, orbit,
// dolly) fitted to a scene's bounds, and a fly controller for windowed mode (input-agnostic).
#pragma once
#include <rrc/projection.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <vector>

namespace rrc::demo {

// Reversed-Z perspective (forwards to rrc::perspectiveReversedZ). With f = 1/tan(fovy/2), n = near,
// F = far and Z = -z_view > 0 the distance along the view direction:
//   clip = (f/aspect * x, f * y, n/(F-n) * z + n*F/(F-n), -z)   so  depth = n*(F - Z) / (Z*(F - n))
//   infinite far plane (F = kInfiniteFar): clip.z = n            so  depth = n / Z
// Depth is 1 at the near plane and falls to 0 at F (or at infinity). Use it with
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), glClearDepth(0) and glDepthFunc(GL_GREATER): float
// depth then keeps precision far away (see enableReversedZ() in target.hpp).
glm::dmat4 perspective(double fovyRadians, double aspect, double near, double far = kInfiniteFar);

struct Camera {
    glm::dvec3 position{0.0, 0.0, 5.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // camera-to-world rotation; looks down its -Z
    double fovy = 0.9;                           // vertical field of view, radians
    double near = 0.1;
    double far = kInfiniteFar;

    glm::dvec3 forward() const;
    glm::dvec3 right() const;
    glm::dvec3 up() const;
    glm::dmat4 view() const;                     // world -> view
    glm::dmat4 projection(double aspect) const;  // perspective() with this camera's fovy/near/far
    glm::dmat4 viewProjection(double aspect) const { return projection(aspect) * view(); }

    // Eye at `eye` looking at `target`; `up` must not be parallel to the view direction.
    void lookAt(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up = {0.0, 1.0, 0.0});
};

// Where a path puts the camera at time t (seconds); the lens stays the camera's own.
struct Pose {
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    void applyTo(Camera& camera) const { camera.lookAt(position, target, up); }
};

using CameraPath = std::function<Pose(double t)>;

struct Bounds {
    glm::dvec3 min{-1.0};
    glm::dvec3 max{1.0};
    glm::dvec3 center() const { return 0.5 * (min + max); }
    glm::dvec3 halfExtent() const { return 0.5 * (max - min); }
};

// Circles `center` at `radius` (in XZ) and eye height `height`, looking at the centre; one
// revolution per `period` seconds.
struct OrbitPath {
    glm::dvec3 center{0.0};
    double radius = 10.0;
    double height = 2.0;
    double period = 20.0;
    double phase = 0.0;   // radians at t = 0
    Pose at(double t) const;
    Pose operator()(double t) const { return at(t); }
    // Radius ~1.85x the larger horizontal half-extent, eye at 62% of the height.
    static OrbitPath fit(const Bounds& bounds);
};

// Moves from `start` along `direction` (the view direction) by `distance` and back, easing with
// 0.5 - 0.5 cos(2 pi t / period) so that speed is continuous at both ends.
struct DollyPath {
    glm::dvec3 start{0.0, 0.0, 10.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};
    double distance = 5.0;
    double period = 12.0;
    Pose at(double t) const;
    Pose operator()(double t) const { return at(t); }
    // From outside the front-right corner towards the centre, stopping short of the bounds.
    static DollyPath fit(const Bounds& bounds);
};

// Catmull-Rom spline through control points, reparameterised by arc length so the camera moves
// at constant speed; one traversal (one loop if closed) per `period` seconds, looking along the
// tangent (`lookAhead` metres ahead, `pitch` radians down).
class FlyPath {
public:
    FlyPath(std::vector<glm::dvec3> points, double period, bool closed = true);
    Pose at(double t) const;
    Pose operator()(double t) const { return at(t); }
    glm::dvec3 positionAt(double t) const;
    double length() const { return cumulative_.back(); }
    double period() const { return period_; }
    double lookAhead = 10.0;
    double pitch = 0.01;
    // A closed loop down one long aisle of a colonnade, around the back, up the other aisle and
    // around the front; for the temple asset it runs at x = +-11.3, y = 3.5 as assets/scenes.md suggests.
    static FlyPath colonnade(const Bounds& bounds, double period = 30.0);

private:
    glm::dvec3 spline(double u) const;   // u in [0, segments]
    std::vector<glm::dvec3> points_;
    std::vector<double> cumulative_;     // arc length at each table sample
    double period_;
    bool closed_;
    int segments_;
};

// One frame of input for FlyController, independent of the windowing library.
struct ControllerInput {
    bool forward = false, back = false, left = false, right = false, up = false, down = false;
    bool fast = false;                // e.g. shift: 4x speed
    bool dragging = false;            // mouse button held: look around
    glm::dvec2 mouseDelta{0.0};       // pixels since the last frame
    double scroll = 0.0;              // wheel steps: scales the speed
    double dt = 0.0;                  // seconds
};

// WASD + QE (down/up) to move, drag to look. Yaw about world +Y, pitch clamped to +-89 degrees.
class FlyController {
public:
    double speed = 5.0;               // metres per second
    double sensitivity = 0.004;       // radians per pixel
    // Takes yaw and pitch from the camera's current orientation.
    void attach(const Camera& camera);
    // Applies the input; returns true when the camera moved or turned.
    bool update(Camera& camera, const ControllerInput& input);

private:
    double yaw_ = 0.0, pitch_ = 0.0;
};

} // namespace rrc::demo
