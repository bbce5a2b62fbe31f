// Scripted camera paths: pure functions of time in double precision, so headless runs (which
// step t = frame / 60 s) see the same camera on every machine and every run.
#include "camera.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rrc::demo {
namespace {

constexpr int kSamplesPerSegment = 64;   // arc-length table resolution

double wrap01(double x) { return x - std::floor(x); }

} // namespace

Pose OrbitPath::at(double t) const {
    const double a = phase + 2.0 * std::numbers::pi * t / period;
    return {.position = {center.x + radius * std::sin(a), height, center.z + radius * std::cos(a)},
            .target = center};
}

OrbitPath OrbitPath::fit(const Bounds& b) {
    const glm::dvec3 h = b.halfExtent();
    const double sy = b.max.y - b.min.y;
    return {.center = {b.center().x, b.min.y + 0.41 * sy, b.center().z},
            .radius = 1.85 * std::max(h.x, h.z),
            .height = b.min.y + 0.62 * sy};
}

Pose DollyPath::at(double t) const {
    const double s = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * t / period);
    const glm::dvec3 d = glm::normalize(direction);
    const glm::dvec3 eye = start + d * (distance * s);
    return {.position = eye, .target = eye + d};
}

DollyPath DollyPath::fit(const Bounds& b) {
    const glm::dvec3 c = b.center(), h = b.halfExtent();
    const double sy = b.max.y - b.min.y;
    const glm::dvec3 start{c.x + 1.76 * h.x, b.min.y + 0.31 * sy, c.z + 1.74 * h.z};
    const glm::dvec3 aim{c.x, b.min.y + 0.36 * sy, c.z + 0.22 * h.z};
    return {.start = start, .direction = glm::normalize(aim - start), .distance = 0.45 * glm::length(aim - start)};
}

FlyPath::FlyPath(std::vector<glm::dvec3> points, double period, bool closed)
    : points_(std::move(points)), period_(period), closed_(closed) {
    if (points_.empty()) points_.push_back(glm::dvec3(0.0));
    if (points_.size() == 1) points_.push_back(points_[0] + glm::dvec3(0.0, 0.0, -1.0));
    segments_ = static_cast<int>(closed_ ? points_.size() : points_.size() - 1);
    const int samples = segments_ * kSamplesPerSegment;
    cumulative_.reserve(static_cast<size_t>(samples) + 1);
    cumulative_.push_back(0.0);
    glm::dvec3 previous = spline(0.0);
    for (int i = 1; i <= samples; ++i) {
        const glm::dvec3 p = spline(static_cast<double>(i) / kSamplesPerSegment);
        cumulative_.push_back(cumulative_.back() + glm::length(p - previous));
        previous = p;
    }
}

glm::dvec3 FlyPath::spline(double u) const {
    const int n = static_cast<int>(points_.size());
    const int seg = std::clamp(static_cast<int>(std::floor(u)), 0, segments_ - 1);
    const double x = u - seg;
    auto point = [&](int i) {
        return points_[static_cast<size_t>(closed_ ? ((i % n) + n) % n : std::clamp(i, 0, n - 1))];
    };
    const glm::dvec3 p0 = point(seg - 1), p1 = point(seg), p2 = point(seg + 1), p3 = point(seg + 2);
    // Uniform Catmull-Rom: C1-continuous, passes through every control point.
    return 0.5 * (2.0 * p1 + (p2 - p0) * x + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * (x * x) +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * (x * x * x));
}

glm::dvec3 FlyPath::positionAt(double t) const {
    const double phase = closed_ ? wrap01(t / period_) : std::clamp(t / period_, 0.0, 1.0);
    const double s = phase * length();
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const size_t i = static_cast<size_t>(std::clamp<std::ptrdiff_t>(it - cumulative_.begin(), 1,
                                                                     static_cast<std::ptrdiff_t>(cumulative_.size()) - 1));
    const double a = cumulative_[i - 1], b = cumulative_[i];
    const double f = b > a ? (s - a) / (b - a) : 0.0;
    return spline((static_cast<double>(i - 1) + f) / kSamplesPerSegment);
}

Pose FlyPath::at(double t) const {
    const glm::dvec3 eye = positionAt(t);
    const double ahead = period_ * lookAhead / std::max(length(), 1e-9);
    glm::dvec3 target = positionAt(t + ahead);
    if (!closed_ && glm::length(target - eye) < 1e-6 * lookAhead) {   // at the end: keep the last heading
        target = eye + (eye - positionAt(period_ - ahead));
    }
    target.y -= lookAhead * std::tan(pitch);
    return {.position = eye, .target = target};
}

FlyPath FlyPath::colonnade(const Bounds& b, double period) {
    const glm::dvec3 c = b.center(), h = b.halfExtent();
    const double y = b.min.y + 0.19 * (b.max.y - b.min.y);
    const double ax = 0.665 * h.x;
    // Straight down each aisle (collinear points up to the ends of the building, so the spline
    // cannot bulge towards the columns), turning outside the bounds; z in units of the half-depth.
    std::vector<glm::dvec3> p;
    for (double z : {1.0, 0.5, 0.0, -0.5, -1.0, -1.26}) p.push_back({c.x + ax, y, c.z + z * h.z});
    p.push_back({c.x, y, c.z - 1.5 * h.z});
    for (double z : {-1.26, -1.0, -0.5, 0.0, 0.5, 1.0, 1.26}) p.push_back({c.x - ax, y, c.z + z * h.z});
    p.push_back({c.x, y, c.z + 1.5 * h.z});
    p.push_back({c.x + ax, y, c.z + 1.26 * h.z});
    return FlyPath(std::move(p), period, true);
}

} // namespace rrc::demo
