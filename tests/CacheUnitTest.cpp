// Cache CPU parts without GL: projections and their near/far, refresh schedule, motion history.
#include <rrc/motion.hpp>
#include <rrc/projection.hpp>
#include <rrc/refresh.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace rrc::test {
namespace {

TEST(Projection, ReversedZMapsNearToOneAndFarToZero) {
    for (double far : {100.0, kInfiniteFar}) {
        const glm::dmat4 p = perspectiveReversedZ(1.0, 1.5, 0.25, far);
        auto depth = [&](double z) { glm::dvec4 c = p * glm::dvec4(0, 0, -z, 1); return c.z / c.w; };
        EXPECT_NEAR(depth(0.25), 1.0, 1e-12);
        EXPECT_NEAR(depth(std::isinf(far) ? 1e300 : far), 0.0, 1e-12);
        const auto range = depthRangeOf(p, true);
        ASSERT_TRUE(range);
        EXPECT_NEAR(range->near, 0.25, 1e-12);
        EXPECT_EQ(std::isinf(range->far), std::isinf(far));
        if (!std::isinf(far)) {
            EXPECT_NEAR(range->far, far, 1e-9);
        }
    }
}

TEST(Projection, StandardMatchesGlmAndRecoversRange) {
    const glm::dmat4 p = perspectiveStandard(0.9, 4.0 / 3.0, 0.1, 500.0);
    const glm::dmat4 g = glm::perspective(0.9, 4.0 / 3.0, 0.1, 500.0);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(p[c][r], g[c][r], 1e-12);
    const auto range = depthRangeOf(p, false);
    ASSERT_TRUE(range);
    EXPECT_NEAR(range->near, 0.1, 1e-12);
    EXPECT_NEAR(range->far, 500.0, 1e-9);
    EXPECT_FALSE(depthRangeOf(glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 10.0), false));
    EXPECT_FALSE(depthRangeOf(glm::dmat4(NAN), true));
}

TEST(Refresh, RoundRobinRefreshesEveryPixelOncePerPeriod) {
    const RefreshDesc d{.policy = RefreshPolicy::RoundRobin, .period = 6, .blockSize = 2};
    for (uint32_t y = 0; y < 40; ++y)
        for (uint32_t x = 0; x < 40; ++x) {
            int refreshes = 0;
            for (uint32_t f = 100; f < 106; ++f) refreshes += refreshScheduled(d, x, y, f);
            EXPECT_EQ(refreshes, 1);
        }
}

TEST(Refresh, RandomRefreshesTheRequestedFraction) {
    const RefreshDesc d{.policy = RefreshPolicy::Random, .fraction = 0.2f, .blockSize = 1};
    int n = 0;
    for (uint32_t y = 0; y < 200; ++y)
        for (uint32_t x = 0; x < 200; ++x) n += refreshScheduled(d, x, y, 7);
    EXPECT_NEAR(n / 40000.0, 0.2, 0.01);
}

TEST(Motion, DoublePrecisionCompositionSurvivesLargeTranslations) {
    const glm::dvec3 far(1e5, -2e5, 3e5);
    const ViewState view{glm::lookAt(far, far + glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0)), perspectiveReversedZ(1.0, 1.0, 0.1)};
    const ViewState near{glm::lookAt(glm::dvec3(0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0)), view.projection};
    const glm::dmat4 modelFar = glm::translate(glm::dmat4(1.0), far + glm::dvec3(0.3, 0.2, -5));
    const glm::dmat4 modelNear = glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, 0.2, -5));
    const DrawMatrices a = composeDrawMatrices(view, view, modelFar, modelFar);
    const DrawMatrices b = composeDrawMatrices(near, near, modelNear, modelNear);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a.modelViewProj[c][r], b.modelViewProj[c][r], 1e-6);
}

TEST(Motion, HistoryReturnsThePreviousModel) {
    MotionHistory h;
    const glm::dmat4 a = glm::translate(glm::dmat4(1.0), {1, 0, 0}), b = glm::translate(glm::dmat4(1.0), {2, 0, 0});
    bool moved = true;
    EXPECT_EQ(h.update(3, a, &moved), a);
    EXPECT_FALSE(moved);
    h.endFrame();
    EXPECT_EQ(h.update(3, b, &moved), a);
    EXPECT_TRUE(moved);
    EXPECT_TRUE(h.anyMoved());
    h.endFrame();
    EXPECT_EQ(h.update(3, b, &moved), b);
    EXPECT_FALSE(h.anyMoved());
    BoneHistory bones;
    const glm::mat4 m1(1.0f), m2(2.0f);
    bones.update(std::span(&m1, 1));
    EXPECT_FALSE(bones.moved());
    bones.update(std::span(&m2, 1));
    EXPECT_EQ(bones.previous()[0], m1);
    EXPECT_TRUE(bones.moved());
}

} // namespace
} // namespace rrc::test
