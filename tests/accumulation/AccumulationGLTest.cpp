// The accumulation renderer on a static scene (the procedural colonnade): cached equals brute force
// where it must (one sample; a still camera, where every sample hits), the weights sum to one, and
// the depth-of-field error shrinks with N towards the many-sample reference in both variants.
#include "accumulation_fixture.hpp"

#include "depth_of_field/lens.hpp"

#include <rrc/image.hpp>

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::test {
namespace {

using accumulation::Variant;

class Accumulation : public AccumulationFixture {
protected:
    // Depth of field through the colonnade: n lens samples (nearest-neighbour order), or the
    // pinhole view n times when aperture is 0.
    std::vector<glm::vec4> render(Variant variant, int n, double aperture, bool moving = false) {
        const glm::dmat4 view = glm::lookAt(glm::dvec3(3.0, 2.0, 9.0), glm::dvec3(0.0, 1.5, 0.0), glm::dvec3(0, 1, 0));
        const glm::dmat4 projection = AccumulationFixture::projection();
        const auto lens = dof::ordered(dof::poissonDisk(n), dof::LensOrder::NearestNeighbour);
        renderer.render(variant, {.statics = scene.draws, .moving = moving}, n, [&](int i, int) {
            return accumulation::SampleView{dof::lensView(view, lens[size_t(i)] * aperture, 6.0), projection};
        }, true);
        return pixels(renderer.result());
    }
};

TEST_F(Accumulation, OneSampleCachedEqualsBruteForce) {
    // The only sample is rendered in full into the cache: the same shading as brute force.
    EXPECT_EQ(render(Variant::Cached, 1, 0.1), render(Variant::Brute, 1, 0.1));
}

TEST_F(Accumulation, StillCameraEverySampleHitsAndEqualsBruteForceExactly) {
    // Eight identical views with the scene flagged as moving, so every sample really runs the
    // lookup (nothing is skipped as a static frame): all hits, copied texel for texel. No
    // refresh, so that nothing but the lookup makes the samples after the first.
    ASSERT_TRUE(renderer.init(kWidth, kHeight, library, {.octaves = 2, .refreshPeriod = 0}).ok());
    const auto cached = render(Variant::Cached, 8, 0.0, true);
    EXPECT_GT(renderer.hitRate(), 0.999);
    EXPECT_EQ(cached, render(Variant::Brute, 8, 0.0, true));
}

TEST_F(Accumulation, WeightsSumToOne) {
    // N copies of one sample, each added with weight 1/N, give the sample back.
    accumulation::Accumulator accumulator;
    ASSERT_TRUE(accumulator.init(kWidth, kHeight, library).ok());
    const auto sample = render(Variant::Brute, 1, 0.0);   // renderer.lastSample: 8-bit colour
    for (int n : {3, 7, 32}) {
        accumulator.clear();
        for (int i = 0; i < n; ++i) accumulator.add(renderer.lastSample(Variant::Brute), 1.0f / float(n));
        const auto sum = pixels(accumulator.result());
        double worst = 0;
        for (size_t i = 0; i < sum.size(); ++i) worst = std::max(worst, double(glm::length(sum[i] - sample[i])));
        EXPECT_LT(worst, 1e-5) << n << " samples";
    }
}

TEST_F(Accumulation, DepthOfFieldErrorShrinksWithSamplesInBothVariants) {
    const auto reference = render(Variant::Brute, 64, 0.15);
    double previous[2] = {1e9, 1e9};
    for (int n : {2, 8, 32}) {
        const double brute = rmse(render(Variant::Brute, n, 0.15), reference);
        const double cached = rmse(render(Variant::Cached, n, 0.15), reference);
        const double hitRate = renderer.hitRate();
        std::printf("N=%2d  RMSE brute %.5f  cached %.5f  hit rate %.3f\n", n, brute, cached, hitRate);
        EXPECT_LT(brute, previous[0]);
        EXPECT_LT(cached, previous[1]);
        // Reuse costs little accuracy: within a quarter of brute force's own sampling error, or 0.004.
        EXPECT_LT(cached, std::max(1.25 * brute, brute + 0.004)) << n << " samples";
        EXPECT_GT(hitRate, 0.5) << n << " samples";
        previous[0] = brute;
        previous[1] = cached;
    }
}

TEST_F(Accumulation, WithoutRefreshTheReuseChainKeepsTheErrorFromFalling) {
    // Each hit resamples the previous sample bilinearly, so a pixel reused k times has been
    // low-pass filtered k times: without refresh the reuse error, not the sampling, dominates at
    // large N (far above brute force's error there; in rrc-bench's motion blur it even grows
    // with N). The round-robin refresh (every block shaded afresh every 4 samples) bounds the
    // chain and keeps the cached error close to brute force's.
    const auto reference = render(Variant::Brute, 64, 0.15);
    const double brute32 = rmse(render(Variant::Brute, 32, 0.15), reference);
    const double refreshed32 = rmse(render(Variant::Cached, 32, 0.15), reference);
    ASSERT_TRUE(renderer.init(kWidth, kHeight, library, {.octaves = 2, .refreshPeriod = 0}).ok());
    const double chained32 = rmse(render(Variant::Cached, 32, 0.15), reference);
    std::printf("N=32 RMSE: brute force %.5f, cached without refresh %.5f, refresh every 4 %.5f\n", brute32, chained32,
                refreshed32);
    EXPECT_GT(chained32, 2.0 * brute32);
    EXPECT_LT(refreshed32, 1.5 * brute32);
}

} // namespace
} // namespace rrc::test
