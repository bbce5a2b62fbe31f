#include "lens.hpp"

#include "support/poisson.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <limits>
#include <random>

namespace rrc::dof {

std::vector<glm::dvec2> poissonDisk(int count, uint32_t seed) {
    std::vector<glm::dvec2> points;
    for (const glm::vec2 p : demo::poissonDisk(count, seed, demo::kGrowingCandidates)) points.emplace_back(p);
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
