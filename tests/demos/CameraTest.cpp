// Camera maths without GL: the reversed-Z projection maps near to depth 1 and far (or infinity)
// to 0; the view matrix; scripted paths are continuous, periodic and deterministic; the fly
// controller moves at its speed.
#include <common/camera.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rrc::demo::test {
namespace {

double depthAt(const glm::dmat4& projection, double distance) {
    const glm::dvec4 clip = projection * glm::dvec4(0.3, -0.2, -distance, 1.0);
    return clip.z / clip.w;
}

TEST(DemoCamera, ReversedZFiniteFarMapsNearTo1AndFarTo0) {
    const glm::dmat4 p = perspective(0.9, 16.0 / 9.0, 0.1, 1000.0);
    EXPECT_NEAR(depthAt(p, 0.1), 1.0, 1e-12);
    EXPECT_NEAR(depthAt(p, 1000.0), 0.0, 1e-12);
    // depth = n (F - Z) / (Z (F - n)), decreasing with distance
    for (double z : {0.2, 1.0, 10.0, 500.0}) {
        EXPECT_NEAR(depthAt(p, z), 0.1 * (1000.0 - z) / (z * (1000.0 - 0.1)), 1e-12) << z;
        EXPECT_GT(depthAt(p, z), depthAt(p, z * 1.01));
    }
}

TEST(DemoCamera, ReversedZInfiniteFarMapsInfinityTo0) {
    const glm::dmat4 p = perspective(0.9, 1.5, 0.25);
    EXPECT_NEAR(depthAt(p, 0.25), 1.0, 1e-12);
    EXPECT_NEAR(depthAt(p, 10.0), 0.025, 1e-12);   // n / Z
    EXPECT_LT(depthAt(p, 1e12), 1e-12);
    EXPECT_GT(depthAt(p, 1e12), 0.0);
    Camera camera;
    camera.near = 0.25;
    EXPECT_EQ(camera.projection(1.5), p);
}

TEST(DemoCamera, LookAtAndViewMatrix) {
    Camera camera;
    camera.lookAt({1.0, 2.0, 3.0}, {4.0, 2.0, -1.0});
    const glm::dvec4 eye = camera.view() * glm::dvec4(1.0, 2.0, 3.0, 1.0);
    const glm::dvec4 target = camera.view() * glm::dvec4(4.0, 2.0, -1.0, 1.0);
    EXPECT_NEAR(glm::length(glm::dvec3(eye)), 0.0, 1e-12);
    EXPECT_NEAR(target.x, 0.0, 1e-12);
    EXPECT_NEAR(target.y, 0.0, 1e-12);
    EXPECT_NEAR(target.z, -5.0, 1e-12);
    EXPECT_NEAR(glm::dot(camera.forward(), glm::dvec3(0.6, 0.0, -0.8)), 1.0, 1e-12);
    EXPECT_NEAR(camera.up().y, 1.0, 1e-12);
}

// Largest |p(t + h) - p(t)| / h over two periods: bounded by the path's top speed.
template <class Path>
double maxSpeed(const Path& path, double period, double h) {
    double worst = 0.0;
    for (double t = -0.5; t < 2.0 * period; t += 0.0137) {
        worst = std::max(worst, glm::length(path.at(t + h).position - path.at(t).position) / h);
    }
    return worst;
}

template <class Path>
double maxTurn(const Path& path, double period, double h) {   // radians per step of the view direction
    double worst = 0.0;
    for (double t = 0.0; t < period; t += 0.0137) {
        const Pose a = path.at(t), b = path.at(t + h);
        const double c = glm::dot(glm::normalize(a.target - a.position), glm::normalize(b.target - b.position));
        worst = std::max(worst, std::acos(std::clamp(c, -1.0, 1.0)));
    }
    return worst;
}

const Bounds kTemple{{-17.0, -0.2, -35.6}, {17.0, 19.15, 35.6}};

TEST(DemoCameraPaths, OrbitIsContinuousPeriodicAndFitsTheBounds) {
    const OrbitPath orbit = OrbitPath::fit(kTemple);
    EXPECT_NEAR(orbit.radius, 65.86, 0.01);
    const double top = 2.0 * std::numbers::pi * orbit.radius / orbit.period;
    EXPECT_LE(maxSpeed(orbit, orbit.period, 1e-4), top * 1.001);
    EXPECT_LT(maxTurn(orbit, orbit.period, 1e-3), 1e-3);
    EXPECT_NEAR(glm::length(orbit.at(3.0).position - orbit.at(3.0 + orbit.period).position), 0.0, 1e-9);
}

TEST(DemoCameraPaths, DollyMovesAlongItsViewDirectionSmoothly) {
    const DollyPath dolly = DollyPath::fit(kTemple);
    const double top = std::numbers::pi * dolly.distance / dolly.period;
    EXPECT_LE(maxSpeed(dolly, dolly.period, 1e-4), top * 1.001);
    const Pose a = dolly.at(0.0), b = dolly.at(dolly.period / 2);
    EXPECT_NEAR(glm::length(b.position - a.position), dolly.distance, 1e-9);
    EXPECT_NEAR(glm::dot(glm::normalize(b.position - a.position), glm::normalize(a.target - a.position)), 1.0, 1e-12);
    // Stops outside the building (the front columns are at z = 32).
    EXPECT_GT(b.position.z, 33.0);
}

TEST(DemoCameraPaths, ColonnadeFlyThroughIsContinuousAtConstantSpeed) {
    const FlyPath fly = FlyPath::colonnade(kTemple);
    const double speed = fly.length() / fly.period();
    EXPECT_GT(speed, 4.0);
    EXPECT_LT(speed, 12.0);
    EXPECT_LE(maxSpeed(fly, fly.period(), 1e-4), speed * 1.05);
    EXPECT_LT(maxTurn(fly, fly.period(), 1e-3), 0.01);
    EXPECT_NEAR(glm::length(fly.positionAt(1.0) - fly.positionAt(1.0 + fly.period())), 0.0, 1e-9);
    // It runs down the aisle between the outer columns (x = 13.5) and the cella wall (x = 9),
    // at eye height ~3.5 m, like the path suggested in assets/scenes.md.
    double closest = 1e9;
    for (double t = 0.0; t < fly.period(); t += 0.01)
        closest = std::min(closest, glm::length(fly.positionAt(t) - glm::dvec3(11.3, 3.5, 0.0)));
    EXPECT_LT(closest, 0.1);
    for (double t = 0.0; t < fly.period(); t += 0.05) {
        const glm::dvec3 p = fly.positionAt(t);
        if (std::abs(p.z) < 30.0) {
            EXPECT_GT(std::abs(p.x), 9.5) << "inside the cella at t = " << t;
        }
    }
}

TEST(DemoCameraPaths, PathsAreDeterministic) {
    const FlyPath a = FlyPath::colonnade(kTemple), b = FlyPath::colonnade(kTemple);
    for (int frame = 0; frame < 600; frame += 7) {
        const double t = frame / 60.0;
        EXPECT_EQ(a.at(t).position, b.at(t).position);
        EXPECT_EQ(a.at(t).target, b.at(t).target);
        EXPECT_EQ(OrbitPath::fit(kTemple).at(t).position, OrbitPath::fit(kTemple).at(t).position);
    }
}

TEST(DemoCameraPaths, OpenPathStopsAtItsEnd) {
    const FlyPath line({{0.0, 0.0, 0.0}, {0.0, 0.0, -10.0}, {0.0, 0.0, -20.0}}, 4.0, false);
    EXPECT_NEAR(line.length(), 20.0, 1e-9);
    EXPECT_NEAR(line.positionAt(2.0).z, -10.0, 1e-6);
    EXPECT_NEAR(line.positionAt(100.0).z, -20.0, 1e-9);
    const Pose end = line.at(100.0);
    EXPECT_LT(end.target.z, end.position.z);   // still looks forward
}

TEST(DemoCameraController, MovesAtItsSpeedAndClampsPitch) {
    Camera camera;
    camera.lookAt({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0});
    FlyController fly;
    fly.attach(camera);
    EXPECT_TRUE(fly.update(camera, {.forward = true, .dt = 1.0}));
    EXPECT_NEAR(camera.position.z, -5.0, 1e-12);
    EXPECT_TRUE(fly.update(camera, {.dragging = true, .mouseDelta = {0.0, -10000.0}}));
    EXPECT_NEAR(std::asin(camera.forward().y), 1.5533, 1e-4);   // clamped at 89 degrees
    EXPECT_FALSE(fly.update(camera, {.dt = 1.0}));
    fly.update(camera, {.scroll = 1.0});
    EXPECT_NEAR(fly.speed, 6.0, 1e-12);
}

} // namespace
} // namespace rrc::demo::test
