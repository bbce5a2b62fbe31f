// Motion blur with the skinned character running past the colonnade and the camera tracking it:
// the cached variant (each time sample looks up the previous sample's cache, with the previous
// sample's bones) hits most pixels and stays as close to the many-sample reference as brute force;
// forcing the character's misses (an object whose look changes within the shutter) costs hits only.
#include "accumulation_fixture.hpp"

#include "motion_blur/shutter.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::test {
namespace {

using accumulation::Variant;

class MotionBlur : public AccumulationFixture {
protected:
    void SetUp() override {
        AccumulationFixture::SetUp();
        auto loaded = accumulation::Character::load(RRC_ASSETS "/character.glb");
        ASSERT_TRUE(loaded.ok());
        character = std::move(loaded).value();
    }
    void TearDown() override {
        character = {};
        AccumulationFixture::TearDown();
    }

    // The character runs along -x in front of the colonnade; the camera follows it, lagging.
    std::vector<glm::vec4> render(Variant variant, int n, bool neverCacheCharacter = false) {
        const motion_blur::Shot shot{.shutter = 1.0 / 30.0};
        const glm::dmat4 projection = AccumulationFixture::projection();
        const accumulation::SceneRef ref{.statics = scene.draws, .character = &character,
                                         .characterNeverCached = neverCacheCharacter};
        renderer.render(variant, ref, n, [&](int i, int count) {
            const double t = motion_blur::sampleTime(shot, 0.2, i, count);
            const glm::dvec3 runner(2.0 - 4.0 * t, 0.8, 3.0);   // on the stylobate
            character.pose(t, glm::rotate(glm::translate(glm::dmat4(1.0), runner), -1.5707963, glm::dvec3(0, 1, 0)));
            const glm::dvec3 eye(2.4 - 3.0 * t, 1.6, 7.0);
            return accumulation::SampleView{glm::lookAt(eye, runner + glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0)), projection};
        }, true);
        return pixels(renderer.result());
    }

    accumulation::Character character;
};

TEST_F(MotionBlur, OneSampleCachedEqualsBruteForce) {
    EXPECT_EQ(render(Variant::Cached, 1), render(Variant::Brute, 1));
}

TEST_F(MotionBlur, CachedSamplesHitAndStayAsCloseToTheReferenceAsBruteForce) {
    const auto reference = render(Variant::Brute, 64);
    const double brute = rmse(render(Variant::Brute, 8), reference);
    const double cached = rmse(render(Variant::Cached, 8), reference);
    const double hitRate = renderer.hitRate();
    const double forcedCached = rmse(render(Variant::Cached, 8, true), reference);
    const double forcedHitRate = renderer.hitRate();
    std::printf("N=8  RMSE brute %.5f  cached %.5f (hit rate %.3f)  character never cached %.5f (hit rate %.3f)\n", brute,
                cached, hitRate, forcedCached, forcedHitRate);
    EXPECT_GT(hitRate, 0.65);   // a quarter of the pixels are refreshed at every sample
    EXPECT_LT(cached, std::max(1.25 * brute, brute + 0.004));
    // Forced misses on the character: fewer hits, and its pixels shaded fresh at every sample.
    EXPECT_LT(forcedHitRate, hitRate - 0.01);
    EXPECT_LT(forcedCached, std::max(1.25 * brute, brute + 0.004));
    // More samples, less error, also for the cached variant.
    EXPECT_LT(rmse(render(Variant::Cached, 32), reference), cached);
}

} // namespace
} // namespace rrc::test
