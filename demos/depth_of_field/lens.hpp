// Depth of field by accumulation (chapter section 6.5.3): camera positions on the lens aperture
// from a deterministic Poisson-disk pattern, an order through them (consecutive views close, so
// the cache of one view serves the next), and the sheared view that keeps the focal plane fixed.
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace rrc::dof {

// `count` points in the unit disk: support/poisson.hpp's best-candidate pattern with Mitchell's
// growing candidate count, in double precision for the view matrices; the same for the same seed.
std::vector<glm::dvec2> poissonDisk(int count, uint32_t seed = 1);
double minDistance(const std::vector<glm::dvec2>& points);

enum class LensOrder { NearestNeighbour, Random };
const char* lensOrderName(LensOrder order);
// NearestNeighbour: a greedy path from the point nearest the centre, always to the nearest point
// not yet visited. Random: a seeded shuffle.
std::vector<glm::dvec2> ordered(std::vector<glm::dvec2> points, LensOrder order, uint32_t seed = 1);
double pathLength(const std::vector<glm::dvec2>& points);   // sum of consecutive distances

// The view from a lens point `offset` (metres, camera x/y) of a thin lens focused at
// `focusDistance`: the eye moves by offset and the view is sheared so that points at that
// distance keep their screen position (Haeberli and Akeley's accumulation-buffer depth of field).
glm::dmat4 lensView(const glm::dmat4& view, glm::dvec2 offset, double focusDistance);

} // namespace rrc::dof
