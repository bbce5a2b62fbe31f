// The lookup on scenes with analytic answers: static camera, a known translation, disocclusion,
// camera cuts, off-screen reprojection, depth discontinuities, object ids and forced misses.
#include "support/cache_scene.hpp"
#include "support/gl_test.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rrc::test {
namespace {

constexpr int W = 128, H = 96;
const Object kWall{.model = quadAt({0, 0, -10}, {40, 40}), .prevModel = quadAt({0, 0, -10}, {40, 40}), .id = 1};

// World point on the plane z = planeZ seen through the centre of pixel (x, y).
glm::dvec3 worldAtPixel(const Camera& c, int x, int y, double planeZ) {
    const glm::dmat4 inv = glm::inverse(c.projection(double(W) / H, true) * c.view());
    const glm::dvec2 ndc((x + 0.5) / W * 2.0 - 1.0, (y + 0.5) / H * 2.0 - 1.0);
    glm::dvec4 a = inv * glm::dvec4(ndc, 1.0, 1.0), b = inv * glm::dvec4(ndc, 0.5, 1.0);
    const glm::dvec3 p0 = glm::dvec3(a) / a.w, p1 = glm::dvec3(b) / b.w;
    const double t = (planeZ - p0.z) / (p1.z - p0.z);
    return p0 + t * (p1 - p0);
}

class CacheLookup : public GLTest {
protected:
    Cache make(CacheDesc desc = {}) {
        desc.width = W;
        desc.height = H;
        if (desc.payloads.size() == 1 && desc.payloads[0].format == GL_RGBA16F) desc.payloads = {{.format = GL_RGBA32F}};
        auto c = Cache::create(desc);
        EXPECT_TRUE(c.ok());
        return std::move(c).value();
    }
};

TEST_F(CacheLookup, StaticCameraHitsEverywhereAndNearestIsBitExact) {
    Cache cache = make({.payloads = {{.format = GL_RGBA32F, .resample = Resample::Nearest}}});
    CacheScene scene(cache);
    const Object objects[] = {kWall, {.model = quadAt({1, 0.5, -5}, {1.5, 1}), .prevModel = quadAt({1, 0.5, -5}, {1.5, 1}), .id = 2}};
    Camera camera{.eye = {0.2, 0.1, 0.0}, .target = {0.3, 0.0, -1.0}};
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    const auto first = readRGBA(cache.payload(0));
    EXPECT_EQ(cache.finishStats().counts[int(Outcome::Invalid)], size_t(W * H));   // first frame: nothing cached
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    const Stats stats = cache.finishStats();
    std::printf("static camera: %llu hits of %d pixels\n", static_cast<unsigned long long>(stats.hits), W * H);
    EXPECT_GE(stats.hitRate(), 0.999);
    EXPECT_EQ(readRGBA(cache.payload(0)), first);  // bit-exact copies
}

TEST_F(CacheLookup, KnownTranslationPutsCachedValuesWhereReprojectionSays) {
    Cache cache = make();
    CacheScene scene(cache);
    const Object objects[] = {kWall};
    Camera a{.eye = {0, 0, 0}, .target = {0, 0, -1}};
    Camera b{.eye = {0.7, -0.4, 0.5}, .target = {0.7, -0.4, -0.5}};
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, a, objects));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, b, objects));
    const auto outcomes = readUint(cache.outcomes());
    const auto payload = readRGBA(cache.payload(0));
    double worst = 0;
    size_t hits = 0, offscreen = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const size_t i = size_t(y) * W + x;
            const glm::dvec3 expected = worldAtPixel(b, x, y, -10.0);
            // Where camera A saw this world point: a hit iff inside A's view.
            const glm::dvec4 clipA = a.projection(double(W) / H, true) * a.view() * glm::dvec4(expected, 1.0);
            const glm::dvec2 uvA = glm::dvec2(clipA) / clipA.w * 0.5 + 0.5;
            const bool insideA = uvA.x > 0.01 && uvA.x < 0.99 && uvA.y > 0.01 && uvA.y < 0.99;
            const bool outsideA = uvA.x < -0.01 || uvA.x > 1.01 || uvA.y < -0.01 || uvA.y > 1.01;
            if (insideA) {
                EXPECT_EQ(outcomes[i], uint32_t(Outcome::Hit)) << x << "," << y;
            }
            if (outsideA) {
                EXPECT_EQ(outcomes[i], uint32_t(Outcome::Offscreen)) << x << "," << y;
            }
            if (outcomes[i] == uint32_t(Outcome::Hit)) {
                ++hits;
                worst = std::max(worst, glm::length(glm::dvec3(payload[i]) - expected));
            }
            offscreen += outcomes[i] == uint32_t(Outcome::Offscreen);
        }
    std::printf("translation: %zu hits, %zu off-screen, worst cached-vs-analytic error %.2e\n", hits, offscreen, worst);
    EXPECT_GT(hits, size_t(W * H / 2));
    EXPECT_GT(offscreen, 0u);
    EXPECT_LT(worst, 1e-3);
}

TEST_F(CacheLookup, MovingOccluderMissesExactlyTheDisoccludedPixels) {
    Cache cache = make({.bilinearDepth = false});
    CacheScene scene(cache);
    Camera camera;
    const glm::dmat4 before = quadAt({-0.613, 0.017, -5}, {1, 1}), after = quadAt({0.219, 0.311, -5}, {1, 1});
    const Object frame1[] = {kWall, {.model = before, .prevModel = before, .id = 2}};
    const Object frame2[] = {kWall, {.model = after, .prevModel = before, .id = 2}};
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, frame1));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, frame2));
    const auto outcomes = readUint(cache.outcomes());
    // The cache holds one sample per texel centre: a surface point reprojecting within half a
    // texel of the occluder's old silhouette may find either surface there, so those pixels are
    // not judged. Everywhere else the outcome is exact.
    const double pixel = 2.0 * 5.0 * std::tan(camera.fovy / 2.0) / H;   // world units at z = -5
    const glm::dvec3 motion = glm::dvec3(after[3] - before[3]);
    size_t expected = 0, mismatched = 0, occluderHits = 0, ambiguous = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            // Analytic coverage: the pixel centre's ray meets the occluder's plane inside the quad.
            const glm::dvec3 p = worldAtPixel(camera, x, y, -5.0);
            auto margin = [&](const glm::dmat4& m, glm::dvec3 q) {   // > 0 inside, in world units
                return std::min(1.0 - std::abs(q.x - m[3].x), 1.0 - std::abs(q.y - m[3].y));
            };
            const bool inAfter = margin(after, p) > 0, inBefore = margin(before, p) > 0;
            if (inAfter && std::abs(margin(before, p - motion)) < 0.5 * pixel) { ++ambiguous; continue; }
            const bool disoccluded = inBefore && !inAfter;
            const uint32_t o = outcomes[size_t(y) * W + x];
            expected += disoccluded;
            mismatched += disoccluded != (o == uint32_t(Outcome::Disoccluded));
            occluderHits += inAfter && o == uint32_t(Outcome::Hit);
        }
    std::printf("moving occluder: %zu disoccluded pixels expected, %zu disagree, %zu occluder pixels hit, "
                "%zu within half a texel of the old silhouette\n", expected, mismatched, occluderHits, ambiguous);
    EXPECT_GT(expected, 100u);
    EXPECT_EQ(mismatched, 0u);
    EXPECT_GT(occluderHits, 100u);   // the moving object itself reprojects with its previous model
}

// The chapter's single-render-target trick: linear depth in payload 0's last channel, one fetch
// for the depth test and the value. Same outcomes as the depth texture, pixel for pixel, for
// RGBA and RG payloads (nearest fetches, so both read the same texel).
TEST_F(CacheLookup, DepthInPayloadGivesTheOutcomesOfTheDepthTexture) {
    Camera camera;
    const Camera moved{.eye = {0.15, -0.1, 0.2}, .target = {0.15, -0.1, -0.8}};
    const glm::dmat4 before = quadAt({-0.613, 0.017, -5}, {1, 1}), after = quadAt({0.219, 0.311, -5}, {1, 1});
    const Object frame1[] = {kWall, {.model = before, .prevModel = before, .id = 2}};
    const Object frame2[] = {kWall, {.model = after, .prevModel = before, .id = 2}};
    auto outcomesOf = [&](CacheDesc desc) {
        desc.width = W;   // not make(): it widens RGBA16F
        desc.height = H;
        auto created = Cache::create(desc);
        EXPECT_TRUE(created.ok());
        if (!created) return std::vector<uint32_t>{};
        Cache cache = std::move(created).value();
        CacheScene scene(cache);
        EXPECT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, frame1));
        EXPECT_TRUE(scene.frame(cache, ControlFlow::TwoPass, moved, frame2));
        return readUint(cache.outcomes());
    };
    const auto reference = outcomesOf({.payloads = {{.format = GL_RGBA32F, .resample = Resample::Nearest}}, .bilinearDepth = false});
    size_t hits = 0, disoccluded = 0;
    for (uint32_t o : reference) {
        hits += o == uint32_t(Outcome::Hit);
        disoccluded += o == uint32_t(Outcome::Disoccluded);
    }
    std::printf("depth in payload: reference %zu hits, %zu disoccluded\n", hits, disoccluded);
    EXPECT_GT(hits, size_t(W * H / 2));
    EXPECT_GT(disoccluded, 100u);
    for (GLenum format : {GL_RGBA32F, GL_RGBA16F, GL_RG32F, GL_RG16F}) {
        const auto outcomes = outcomesOf({.payloads = {{.format = format, .resample = Resample::Nearest}}, .depthInPayload = true});
        size_t differ = 0;
        for (size_t i = 0; i < outcomes.size(); ++i) differ += outcomes[i] != reference[i];
        EXPECT_EQ(differ, 0u) << "format 0x" << std::hex << format;
    }
}

TEST_F(CacheLookup, InvalidateMakesEverythingMissAndSkipsTheLookup) {
    Cache cache = make();
    CacheScene scene(cache);
    const Object objects[] = {kWall};
    Camera camera;
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    EXPECT_EQ(cache.finishStats().hits, size_t(W * H));
    cache.invalidate();
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    const Stats s = cache.finishStats();
    EXPECT_EQ(s.hits, 0u);
    EXPECT_EQ(s.counts[int(Outcome::Invalid)], size_t(W * H));
    EXPECT_EQ(scene.passes, (std::vector<Pass>{Pass::DepthPrepass, Pass::Miss}));   // no lookup, no probe
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    EXPECT_EQ(cache.finishStats().hits, size_t(W * H));
}

TEST_F(CacheLookup, NoHitTakesItsValueAcrossADepthDiscontinuity) {
    Cache cache = make();
    CacheScene scene(cache);
    const glm::dmat4 box = quadAt({0.1, -0.2, -3}, {0.8, 0.6});
    const Object objects[] = {kWall, {.model = box, .prevModel = box, .id = 2}};
    Camera a, b{.eye = {0.31, 0.12, 0.2}, .target = {0.25, 0.1, -1}};
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, a, objects));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, b, objects));
    const auto outcomes = readUint(cache.outcomes());
    const auto cached = readRGBA(cache.payload(0));
    // Reference: the same view with everything shaded afresh.
    Cache ref = make();
    CacheScene refScene(ref);
    ASSERT_TRUE(refScene.frame(ref, ControlFlow::TwoPass, b, objects));
    const auto truth = readRGBA(ref.payload(0));
    double worst = 0;
    size_t hits = 0, disoccluded = 0;
    for (size_t i = 0; i < truth.size(); ++i) {
        if (outcomes[i] != uint32_t(Outcome::Hit)) { disoccluded += outcomes[i] == uint32_t(Outcome::Disoccluded); continue; }
        ++hits;
        worst = std::max(worst, double(glm::length(glm::vec3(cached[i]) - glm::vec3(truth[i]))));
    }
    std::printf("discontinuity: %zu hits, %zu disoccluded, worst hit error %.2e world units\n", hits, disoccluded, worst);
    EXPECT_GT(disoccluded, 0u);
    EXPECT_LT(worst, 0.1);   // a value taken from the other surface would be off by metres
}

TEST_F(CacheLookup, ObjectIdKeySeparatesSurfacesAtTheSameDepth) {
    const glm::dmat4 plane = quadAt({0, 0, -4}, {10, 10});
    const Object first[] = {{.model = plane, .prevModel = plane, .id = 7}};
    const Object second[] = {{.model = plane, .prevModel = plane, .id = 8}};   // another surface, same place
    Camera camera;
    for (bool useIds : {false, true}) {
        Cache cache = make({.objectIds = useIds});
        CacheScene scene(cache);
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, first));
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, second));
        const Stats s = cache.finishStats();
        if (useIds) {
            EXPECT_EQ(s.hits, 0u);
            EXPECT_EQ(s.counts[int(Outcome::IdMismatch)], size_t(W * H));
        } else {
            EXPECT_EQ(s.hits, size_t(W * H));   // depth alone cannot tell them apart
        }
    }
}

TEST_F(CacheLookup, ForcedMissesAreHonoured) {
    Cache cache = make({.maxScale = 1.5f});
    CacheScene scene(cache);
    const glm::dmat4 left = quadAt({-1.2, 0, -5}, {0.8, 0.8}), right = quadAt({1.2, 0, -5}, {0.8, 0.8});
    Object objects[] = {kWall, {.model = left, .prevModel = left, .id = 2, .neverCache = true},
                        {.model = right, .prevModel = right, .id = 3, .forceMiss = true}};
    Camera camera;
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
    const auto outcomes = readUint(cache.outcomes());
    size_t forced = 0, forcedExpected = 0, wrong = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const glm::dvec3 p = worldAtPixel(camera, x, y, -5.0);
            const bool onLeft = std::abs(p.x + 1.2) < 0.8 && std::abs(p.y) < 0.8;
            const bool onRight = std::abs(p.x - 1.2) < 0.8 && std::abs(p.y) < 0.8;
            const uint32_t o = outcomes[size_t(y) * W + x];
            forcedExpected += onLeft || onRight;
            forced += o == uint32_t(Outcome::Forced);
            wrong += (onLeft || onRight) != (o == uint32_t(Outcome::Forced));
        }
    EXPECT_GT(forcedExpected, 200u);
    EXPECT_EQ(wrong, 0u) << forced << " forced of " << forcedExpected;
    // Magnification by more than maxScale (a 2x zoom) forces misses everywhere.
    Camera zoomed{.fovy = 2.0 * std::atan(std::tan(0.5) / 2.0)};
    objects[1].neverCache = objects[2].forceMiss = false;
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, zoomed, objects));
    EXPECT_EQ(cache.finishStats().forced, size_t(W * H));
}

} // namespace
} // namespace rrc::test
