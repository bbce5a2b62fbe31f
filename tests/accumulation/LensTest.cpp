// Depth-of-field lens sampling and the motion-blur shutter, without GL: the Poisson-disk pattern
// (inside the disk, spaced, deterministic), the sample orders, the focal-plane-preserving view.
#include "depth_of_field/lens.hpp"
#include "motion_blur/shutter.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace rrc::test {
namespace {

TEST(Lens, PoissonDiskPointsAreInsideTheDiskAndSpacedLikeBlueNoise) {
    for (int n : {4, 8, 16, 32, 64}) {
        const auto points = dof::poissonDisk(n, 1);
        ASSERT_EQ(points.size(), size_t(n));
        for (const glm::dvec2& p : points) EXPECT_LE(glm::length(p), 1.0);
        // Hexagonal packing of n points in the unit disk spaces them sqrt(2 pi / (sqrt 3 n)) apart;
        // best-candidate sampling keeps well over half of that (uniform random points do not:
        // their nearest pair shrinks like 1/n).
        const double hex = std::sqrt(2.0 * std::numbers::pi / (std::sqrt(3.0) * n));
        EXPECT_GT(dof::minDistance(points), 0.5 * hex) << n << " points";
    }
}

TEST(Lens, PoissonDiskIsDeterministicPerSeed) {
    EXPECT_EQ(dof::poissonDisk(16, 7), dof::poissonDisk(16, 7));
    EXPECT_NE(dof::poissonDisk(16, 7), dof::poissonDisk(16, 8));
}

TEST(Lens, OrdersArePermutationsAndNearestNeighbourWalksLess) {
    for (int n : {8, 16, 32, 64}) {
        const auto points = dof::poissonDisk(n, 3);
        auto sorted = [](std::vector<glm::dvec2> v) {
            std::sort(v.begin(), v.end(), [](auto a, auto b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
            return v;
        };
        const auto nearest = dof::ordered(points, dof::LensOrder::NearestNeighbour);
        EXPECT_EQ(sorted(nearest), sorted(points));
        double randomLength = 0;
        for (uint32_t seed = 1; seed <= 8; ++seed) {
            const auto random = dof::ordered(points, dof::LensOrder::Random, seed);
            EXPECT_EQ(sorted(random), sorted(points));
            randomLength += dof::pathLength(random) / 8;
        }
        // The greedy path is shorter than a random tour on average, by far once there are more
        // than a handful of points (steps ~ the Poisson spacing against ~0.9 radii).
        std::printf("%2d points: nearest-neighbour path %.2f, random order %.2f (mean of 8)\n", n,
                    dof::pathLength(nearest), randomLength);
        EXPECT_LT(dof::pathLength(nearest), (n >= 16 ? 0.7 : 1.0) * randomLength) << n << " points";
        for (const glm::dvec2& p : points) EXPECT_GE(glm::length(p), glm::length(nearest.front()));
    }
}

TEST(Lens, LensViewKeepsTheFocalPlaneAndMovesEverythingElse) {
    const glm::dmat4 view = glm::lookAt(glm::dvec3(1, 2, 10), glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(0.9, 4.0 / 3.0, 0.1, 100.0);
    auto screen = [&](const glm::dmat4& v, glm::dvec3 world) {
        const glm::dvec4 c = projection * v * glm::dvec4(world, 1.0);
        return glm::dvec2(c) / c.w;
    };
    const double focus = 6.0;
    const glm::dmat4 inverse = glm::inverse(view);
    auto ahead = [&](double distance, glm::dvec2 side) {   // a world point `distance` in front of the eye
        return glm::dvec3(inverse * glm::dvec4(side, -distance, 1.0));
    };
    for (glm::dvec2 offset : {glm::dvec2(0.1, 0.0), glm::dvec2(-0.05, 0.08)}) {
        const glm::dmat4 lens = dof::lensView(view, offset, focus);
        const glm::dvec3 inFocus = ahead(focus, {0.7, -0.3}), near = ahead(2.0, {0.2, 0.1});
        EXPECT_LT(glm::distance(screen(lens, inFocus), screen(view, inFocus)), 1e-12);
        EXPECT_GT(glm::distance(screen(lens, near), screen(view, near)), 1e-2);
        // The eye itself moved by the offset: the lens view's origin is the moved eye.
        const glm::dvec3 eye(glm::inverse(lens)[3]);
        EXPECT_LT(glm::distance(eye, glm::dvec3(inverse * glm::dvec4(offset, 0.0, 1.0))), 1e-12);
    }
}

TEST(Lens, ShutterSamplesAreMidpointsOfEqualStrata) {
    const motion_blur::Shot shot{.shutter = 0.04};
    for (int n : {1, 2, 8, 64}) {
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            const double t = motion_blur::sampleTime(shot, 1.0, i, n);
            EXPECT_GT(t, 1.0);
            EXPECT_LT(t, 1.04);
            sum += t;
        }
        EXPECT_NEAR(sum / n, 1.02, 1e-12);   // centred on the middle of the shutter interval
    }
}

} // namespace
} // namespace rrc::test
