#include "lens.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <limits>
#include <random>

namespace rrc::dof {

std::vector<glm::dvec2> poissonDisk(int count, uint32_t seed) {
    // mt19937's output is fixed by the standard; the distributions are not, so convert ourselves
    // (the same pattern with every standard library: golden frames depend on it).
    std::mt19937 rng(seed);
    auto unit = [&] { return double(rng()) / 2147483648.0 - 1.0; };
    auto inDisk = [&] {
        for (;;) {
            const glm::dvec2 p(unit(), unit());
            if (glm::dot(p, p) <= 1.0) return p;
        }
    };
    std::vector<glm::dvec2> points;
    for (int i = 0; i < count; ++i) {
        glm::dvec2 best = inDisk();
        double bestDistance = -1.0;
        const int candidates = 10 * (i + 1);   // Mitchell's rule: candidates grow with the points
        for (int c = 0; c < candidates && !points.empty(); ++c) {
            const glm::dvec2 p = c == 0 ? best : inDisk();
            double nearest = std::numeric_limits<double>::infinity();
            for (const glm::dvec2& q : points) nearest = std::min(nearest, glm::distance(p, q));
            if (nearest > bestDistance) { bestDistance = nearest; best = p; }
        }
        points.push_back(best);
    }
    return points;
}

double minDistance(const std::vector<glm::dvec2>& points) {
    double d = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = i + 1; j < points.size(); ++j) d = std::min(d, glm::distance(points[i], points[j]));
    return d;
}

const char* lensOrderName(LensOrder order) { return order == LensOrder::NearestNeighbour ? "nearest" : "random"; }

std::vector<glm::dvec2> ordered(std::vector<glm::dvec2> points, LensOrder order, uint32_t seed) {
    if (points.empty()) return points;
    if (order == LensOrder::Random) {
        std::mt19937 rng(seed);   // Fisher-Yates by hand: std::shuffle differs between libraries
        for (size_t i = points.size() - 1; i > 0; --i) std::swap(points[i], points[rng() % (i + 1)]);
        return points;
    }
    auto centre = std::min_element(points.begin(), points.end(),
                                   [](const glm::dvec2& a, const glm::dvec2& b) { return glm::dot(a, a) < glm::dot(b, b); });
    std::iter_swap(points.begin(), centre);
    for (size_t i = 1; i < points.size(); ++i) {
        auto next = std::min_element(points.begin() + long(i), points.end(), [&](const glm::dvec2& a, const glm::dvec2& b) {
            return glm::distance(a, points[i - 1]) < glm::distance(b, points[i - 1]);
        });
        std::iter_swap(points.begin() + long(i), next);
    }
    return points;
}

double pathLength(const std::vector<glm::dvec2>& points) {
    double length = 0.0;
    for (size_t i = 1; i < points.size(); ++i) length += glm::distance(points[i - 1], points[i]);
    return length;
}

glm::dmat4 lensView(const glm::dmat4& view, glm::dvec2 offset, double focusDistance) {
    // Moving the eye by +offset moves the world by -offset in view space; then x' += k * z with
    // k = -offset / F puts a point at z = -F (distance F ahead) back where it was.
    glm::dmat4 shear(1.0);
    shear[2][0] = -offset.x / focusDistance;
    shear[2][1] = -offset.y / focusDistance;
    return shear * glm::translate(glm::dmat4(1.0), glm::dvec3(-offset, 0.0)) * view;
}

} // namespace rrc::dof
