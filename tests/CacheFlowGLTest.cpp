// Control flow, refresh, amortization: the three flows render identical images, the miss pass
// is skipped when nothing missed, a frame where nothing moved draws nothing, refresh policies
// refresh exactly their scheduled pixels, and the recursive filter has the variance it promises.
#include "support/cache_scene.hpp"
#include "support/gl_test.hpp"
#include "support/log_capture.hpp"

#include <cmath>

namespace rrc::test {
namespace {

constexpr int W = 96, H = 64;

class CacheFlow : public GLTest {
protected:
    Cache make(CacheDesc desc = {}) {
        desc.width = W;
        desc.height = H;
        desc.payloads = {{.format = GL_RGBA32F, .resample = desc.payloads[0].resample}};
        auto c = Cache::create(desc);
        EXPECT_TRUE(c.ok());
        return std::move(c).value();
    }
    const glm::dmat4 wall = quadAt({0, 0, -10}, {40, 40});
};

TEST_F(CacheFlow, OneTwoAndThreePassFlowsRenderIdenticalImages) {
    // `two` marks misses from its outcome target; `noStats` (no outcome target) by the stencil
    // its lookup pass writes, with the probe drawn by the application.
    Cache one = make(), two = make(), three = make(), noPrepass = make(), noStats = make({.stats = false});
    // Without stencil (a plain depth buffer): the flows that need none.
    Cache oneNoStencil = make({.stencil = false}), twoNoStencil = make({.stencil = false});
    CacheScene s1(one), s2(two), s3(three), s4(noPrepass), s5(noStats), s6(oneNoStencil), s7(twoNoStencil);
    std::vector<std::vector<glm::vec4>> images[7];
    for (int f = 0; f < 5; ++f) {
        const glm::dmat4 box = quadAt({-1.0 + 0.37 * f, 0.2 - 0.11 * f, -4}, {0.9, 0.7});
        const glm::dmat4 prevBox = quadAt({-1.0 + 0.37 * (f - 1), 0.2 - 0.11 * (f - 1), -4}, {0.9, 0.7});
        const Object objects[] = {{.model = wall, .prevModel = wall, .id = 1}, {.model = box, .prevModel = prevBox, .id = 2}};
        Camera camera{.eye = {0.13 * f, 0.05 * f, 0.1 * f}, .target = {0.1 * f, 0.0, -1.0}};
        ASSERT_TRUE(s1.frame(one, ControlFlow::OnePass, camera, objects));
        ASSERT_TRUE(s2.frame(two, ControlFlow::TwoPass, camera, objects));
        ASSERT_TRUE(s3.frame(three, ControlFlow::ThreePass, camera, objects));
        ASSERT_TRUE(s4.frame(noPrepass, ControlFlow::TwoPass, camera, objects, {.depthPrepass = false}));
        ASSERT_TRUE(s5.frame(noStats, ControlFlow::TwoPass, camera, objects));
        ASSERT_TRUE(s6.frame(oneNoStencil, ControlFlow::OnePass, camera, objects));
        ASSERT_TRUE(s7.frame(twoNoStencil, ControlFlow::TwoPass, camera, objects, {.depthPrepass = false}));
        images[6].push_back(readRGBA(twoNoStencil.payload(0)));
        images[5].push_back(readRGBA(oneNoStencil.payload(0)));
        images[4].push_back(readRGBA(noStats.payload(0)));
        images[3].push_back(readRGBA(noPrepass.payload(0)));
        images[0].push_back(readRGBA(one.payload(0)));
        images[1].push_back(readRGBA(two.payload(0)));
        images[2].push_back(readRGBA(s3.resolved.id()));
        EXPECT_EQ(readUint(one.outcomes()), readUint(two.outcomes())) << "frame " << f;
    }
    EXPECT_EQ(s1.passes, (std::vector<Pass>{Pass::DepthPrepass, Pass::Shade}));
    EXPECT_EQ(s2.passes, (std::vector<Pass>{Pass::DepthPrepass, Pass::Lookup, Pass::Miss}));
    EXPECT_EQ(s3.passes, (std::vector<Pass>{Pass::DepthPrepass, Pass::Lookup, Pass::Miss, Pass::Resolve}));
    EXPECT_EQ(s4.passes, (std::vector<Pass>{Pass::Lookup, Pass::Probe, Pass::Miss}));
    EXPECT_EQ(s5.passes, (std::vector<Pass>{Pass::DepthPrepass, Pass::Lookup, Pass::Probe, Pass::Miss}));
    for (int f = 0; f < 5; ++f) {
        EXPECT_EQ(images[0][f], images[1][f]) << "one-pass vs two-pass, frame " << f;
        EXPECT_EQ(images[1][f], images[2][f]) << "two-pass vs three-pass, frame " << f;
        EXPECT_EQ(images[1][f], images[3][f]) << "two-pass with vs without prepass, frame " << f;
        EXPECT_EQ(images[1][f], images[4][f]) << "two-pass marked by outcome vs by stencil, frame " << f;
        EXPECT_EQ(images[0][f], images[5][f]) << "one-pass with vs without stencil, frame " << f;
        EXPECT_EQ(images[3][f], images[6][f]) << "two-pass without prepass, with vs without stencil, frame " << f;
    }
    // The flow that needs the stencil is refused with a defined error, drawing nothing.
    LogCapture log;
    ASSERT_TRUE(twoNoStencil.beginFrame({.view = glm::dmat4(1.0), .projection = Camera{}.projection(1.5, true)}).ok());
    bool drew = false;
    EXPECT_FALSE(twoNoStencil.render(ControlFlow::TwoPass, [&](Pass) { drew = true; }).ok());
    EXPECT_TRUE(log.has(LogId::CacheBadArgument));
    EXPECT_FALSE(drew);
    twoNoStencil.endFrame();
}

TEST_F(CacheFlow, MissPassIsSkippedWhenNothingMissed) {
    Cache cache = make();
    CacheScene scene(cache);
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    Camera camera;
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    EXPECT_EQ(scene.missFragments(), uint32_t(W * H));   // first frame: all shaded by the miss pass
    // objectsMoved (the default) keeps the frame from being skipped as static: the lookup runs,
    // everything hits, and the conditional miss pass never runs a fragment.
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    EXPECT_EQ(cache.finishStats().hits, uint32_t(W * H));
    EXPECT_EQ(scene.missFragments(), 0u);
    Camera moved{.eye = {0.5, 0, 0}, .target = {0.5, 0, -1}};
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, moved, objects));
    const Stats s = cache.finishStats();
    EXPECT_GT(scene.missFragments(), 0u);
    EXPECT_EQ(scene.missFragments(), s.misses);   // one miss-shader run per missing pixel
}

TEST_F(CacheFlow, FrameWhereNothingMovedDrawsNothing) {
    Cache cache = make();
    CacheScene scene(cache);
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    Camera camera;
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    const auto image = readRGBA(cache.payload(0));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects, {.objectsMoved = false}));
    EXPECT_TRUE(cache.staticFrame());
    EXPECT_TRUE(scene.passes.empty());
    EXPECT_EQ(readRGBA(cache.payload(0)), image);
    // A refresh policy (which needs a cache compiled for it), forced misses or a moved camera
    // all need a real frame.
    {
        LogCapture log;
        EXPECT_FALSE(cache.beginFrame({.view = camera.view(), .projection = camera.projection(1.5, true),
                                       .refresh = {.policy = RefreshPolicy::Full}}).ok());
        EXPECT_TRUE(log.has(LogId::CacheBadArgument));
    }
    cache = make({.refresh = true});
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects, {.objectsMoved = false}));
    EXPECT_TRUE(cache.staticFrame());
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects, {.refresh = {.policy = RefreshPolicy::RoundRobin}, .objectsMoved = false}));
    EXPECT_FALSE(cache.staticFrame());
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects, {.forcedMisses = true, .objectsMoved = false}));
    EXPECT_FALSE(cache.staticFrame());
}

TEST_F(CacheFlow, RefreshPoliciesRefreshExactlyTheirScheduledPixels) {
    const RefreshDesc policies[] = {
        {.policy = RefreshPolicy::Full},
        {.policy = RefreshPolicy::Random, .fraction = 0.25f, .blockSize = 1},
        {.policy = RefreshPolicy::Random, .fraction = 0.1f, .blockSize = 8},
        {.policy = RefreshPolicy::RoundRobin, .period = 4, .blockSize = 1},
        {.policy = RefreshPolicy::RoundRobin, .period = 5, .blockSize = 2},
        {.policy = RefreshPolicy::RoundRobin, .period = 8, .blockSize = 4},
        {.policy = RefreshPolicy::RoundRobin, .period = 3, .blockSize = 8},
    };
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    Camera camera;
    for (const RefreshDesc& refresh : policies) {
        Cache cache = make({.refresh = true});
        CacheScene scene(cache);
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
        for (int f = 0; f < 3; ++f) {
            ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects, {.refresh = refresh}));
            const auto outcomes = readUint(cache.outcomes());
            size_t wrong = 0, refreshed = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const bool expected = refreshScheduled(refresh, x, y, static_cast<uint32_t>(cache.frame()));
                    const bool got = outcomes[size_t(y) * W + x] == uint32_t(Outcome::Refreshed);
                    wrong += expected != got;
                    refreshed += got;
                }
            EXPECT_EQ(wrong, 0u) << "policy " << int(refresh.policy) << " block " << refresh.blockSize;
            EXPECT_GT(refreshed, 0u);
        }
    }
}

TEST_F(CacheFlow, RoundRobinRefreshBoundsTheAgeOfEveryPixel) {
    for (uint32_t period : {2u, 4u, 7u}) {
        Cache cache = make({.age = true, .refresh = true});
        CacheScene scene(cache);
        const Object objects[] = {{.model = wall, .prevModel = wall}};
        Camera camera;
        uint32_t maxAge = 0;
        for (uint32_t f = 0; f < 3 * period + 2; ++f) {
            ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects,
                                    {.refresh = {.policy = RefreshPolicy::RoundRobin, .period = period, .blockSize = 4}}));
            // The age target is attachment 1 (after the payload).
            GLuint ageTexture = 0;
            glGetNamedFramebufferAttachmentParameteriv(cache.framebuffer(), GL_COLOR_ATTACHMENT1,
                                                       GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, reinterpret_cast<GLint*>(&ageTexture));
            for (uint32_t a : readUint(ageTexture)) maxAge = std::max(maxAge, a);
        }
        std::printf("round robin period %u: max age %u\n", period, maxAge);
        EXPECT_EQ(maxAge, period - 1);   // refreshed at least every `period` frames, and no sooner
    }
}

TEST_F(CacheFlow, RecursiveFilterVarianceIsOneMinusLambdaOverOnePlusLambda) {
    for (float lambda : {0.6f, 0.8f}) {
        Cache cache = Cache::create({.width = 256, .height = 256, .payloads = {{.format = GL_RGBA32F, .resample = Resample::Nearest}},
                                     .age = true}).value();
        CacheScene scene(cache, Shading::Amortized);
        const glm::dmat4 plane = quadAt({0, 0, -10}, {40, 40});
        const Object objects[] = {{.model = plane, .prevModel = plane}};
        Camera camera;
        for (int f = 0; f < 80; ++f)
            ASSERT_TRUE(scene.frame(cache, ControlFlow::OnePass, camera, objects, {.lambda = lambda}));
        const auto image = readRGBA(cache.payload(0));
        double sum = 0, sum2 = 0;
        for (const auto& p : image) { sum += p.y; sum2 += double(p.y) * p.y; }
        const double n = double(image.size()), mean = sum / n, variance = sum2 / n - mean * mean;
        const double expected = (1.0 / 12.0) * (1.0 - lambda) / (1.0 + lambda);
        std::printf("lambda %.2f: mean %.4f (0.5), variance %.5f, expected %.5f, ratio %.3f\n", lambda, mean, variance,
                    expected, variance / expected);
        EXPECT_NEAR(mean, 0.5, 0.01);
        EXPECT_NEAR(variance / expected, 1.0, 0.05);   // 65536 samples: sampling error ~1%
    }
}

TEST_F(CacheFlow, BlendNeverWritesOrReadsNonFiniteValues) {
    Cache cache = Cache::create({.width = 64, .height = 64, .payloads = {{.format = GL_RGBA32F}}, .age = true}).value();
    CacheScene scene(cache, Shading::Amortized);
    const glm::dmat4 plane = quadAt({0, 0, -10}, {40, 40});
    const Object objects[] = {{.model = plane, .prevModel = plane}};
    Camera camera;
    for (float offset : {0.0f, NAN, INFINITY, -INFINITY, 0.0f}) {
        scene.sampleOffset = offset;
        ASSERT_TRUE(scene.frame(cache, ControlFlow::OnePass, camera, objects, {.lambda = 0.6f}));
        size_t nonFinite = 0;
        for (const auto& p : readRGBA(cache.payload(0))) nonFinite += !std::isfinite(p.x);
        EXPECT_EQ(nonFinite, 0u) << "fresh sample offset " << offset;
    }
}

} // namespace
} // namespace rrc::test
