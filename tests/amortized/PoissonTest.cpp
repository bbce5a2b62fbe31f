// The shared sampling patterns (demos/support/poisson.hpp): inside the unit disk, deterministic,
// and blue-noise spaced (far better than random points), also for every prefix (k taps = the
// first k points of the 256-point pattern).
#include "support/poisson.hpp"

#include <gtest/gtest.h>

#include <cmath>

using rrc::demo::minimumSpacing;
using rrc::demo::poissonDisk;

TEST(Poisson, InsideTheUnitDiskAndDeterministic) {
    const auto a = poissonDisk(256, 7), b = poissonDisk(256, 7), c = poissonDisk(256, 8);
    ASSERT_EQ(a.size(), 256u);
    for (const auto& p : a) EXPECT_LT(std::hypot(p.x, p.y), 1.0f);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(Poisson, EveryPrefixIsWellSpaced) {
    const auto points = poissonDisk(256, 7);
    for (int k : {4, 16, 64, 256}) {
        const std::vector<glm::vec2> prefix(points.begin(), points.begin() + k);
        // k points of minimum spacing d cover at least k discs of radius d/2 inside a disc of
        // radius 1 + d/2, so d <= ~2/sqrt(k); best-candidate reaches about half of that, while
        // uniform random points have expected minimum spacing ~1/k.
        const float spacing = minimumSpacing(prefix);
        EXPECT_GT(spacing, 0.75f / std::sqrt(float(k))) << "k = " << k;
        EXPECT_LT(spacing, 2.1f / std::sqrt(float(k))) << "k = " << k;
    }
}

TEST(Poisson, TapsCoverTheDiskEvenly) {
    // Half the area lies inside radius 1/sqrt(2): about half of the taps must too.
    const auto points = poissonDisk(256, 7);
    int inner = 0;
    for (const auto& p : points) inner += std::hypot(p.x, p.y) < std::sqrt(0.5f);
    EXPECT_NEAR(inner, 128, 16);
}
