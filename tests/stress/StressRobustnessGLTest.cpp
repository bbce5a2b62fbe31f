// Robustness: non-finite payloads (issue item h), edge arguments (i), camera cuts, resizes and
// projection changes (j), misuse of the API (k), and resource and GL state hygiene (l).
#include "stress_scene.hpp"
#include "support/gl_test.hpp"
#include "support/log_capture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rrc::test {
namespace {

class StressRobustness : public GLTest {};

const glm::dmat4 kWall = quadAt({0, 0, -10}, {40, 40});

size_t nonFinite(const std::vector<glm::vec4>& image, int channels = 4) {
    size_t n = 0;
    for (const auto& p : image)
        for (int c = 0; c < channels; ++c) n += !std::isfinite(p[c]);
    return n;
}

// Issue item h. The application itself writes NaN, +Inf and -Inf into 30% of the payload (its
// miss shader on frame 0, its hit shader on frame 6, bypassing rrc_firstSample), and on frame 11
// its fresh samples are non-finite in 30% of the pixels. With the library's blend every
// non-finite value is gone on the next frame; a plain copy of the cache keeps (and with
// filtering spreads) them.
TEST_F(StressRobustness, NonFinitePayloadIsRecoveredByTheBlend) {
    constexpr int W = 64, H = 48, kFrames = 14;
    const std::string body = R"(
vec4 nonFinite(uint salt) {
    uint h = rrc_hash(uvec3(uvec2(gl_FragCoord.xy), salt)) % 10u;
    float v = h == 0u ? uintBitsToFloat(0x7fc00000u) : h == 1u ? uintBitsToFloat(0x7f800000u) : uintBitsToFloat(0xff800000u);
    return h < 3u ? vec4(v) : vec4(0.5);
}
bool injected(uint salt) { return rrc_hash(uvec3(uvec2(gl_FragCoord.xy), salt)) % 10u < 3u; }
vec4 noise() {
    vec4 n = vec4(rrc_hashToUnit(rrc_hash(uvec3(uvec2(gl_FragCoord.xy), u_frame + 17u))));
    return u_params.z > 0.5 && injected(u_frame) ? nonFinite(u_frame) : n;
}
vec4 onMiss() {
    if (u_params.x > 0.5 && injected(99u)) return nonFinite(99u);   // the application's own write
    return rrc_storeAmortized(rrc_firstSample(noise()));
}
vec4 onHit(rrc_Lookup l, vec4 cached) {
    if (u_params.y > 0.5 && injected(77u)) return nonFinite(77u);   // the application's own write
#ifdef COPY
    return cached;
#else
    return rrc_storeAmortized(rrc_blend(cached, noise(), l.age, 0.8));
#endif
}
)";
    const Object objects[] = {{.model = kWall, .prevModel = kWall}};
    for (GLenum format : {GL_RGBA32F, GL_RGBA16F}) {
        for (Resample resample : {Resample::Bilinear, Resample::Nearest}) {
            for (bool copy : {false, true}) {
                Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = format, .resample = resample}},
                                             .age = true}).value();
                std::vector<Define> extra;
                if (copy) extra.push_back({"COPY"});
                StressScene scene(cache, body, extra);
                std::string counts;
                size_t afterInjection = 0;
                for (int f = 0; f < kFrames; ++f) {
                    scene.params = glm::vec4(f == 0 ? 1.0f : 0.0f, f == 6 ? 1.0f : 0.0f, f == 11 ? 1.0f : 0.0f, 0.0f);
                    // A camera moving 0.044 px per frame: filtered (not snapped) fetches.
                    Camera camera{.eye = {f * 0.01, 0, 0}, .target = {f * 0.01, 0, -1}};
                    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
                    const size_t n = nonFinite(readRGBA(cache.payload(0)), 1);
                    counts += (f ? " " : "") + std::to_string(n);
                    if (!copy && f != 0 && f != 6) afterInjection += n;
                }
                std::printf("non-finite %-11s %-8s %-5s: non-finite pixels per frame (NaN/Inf written by the app on "
                            "frames 0 and 6, fresh samples on 11): %s\n", formatName(format),
                            resample == Resample::Nearest ? "nearest" : "bilinear", copy ? "copy" : "blend", counts.c_str());
                if (!copy) {
                    EXPECT_EQ(afterInjection, 0u) << formatName(format) << ": the blend must flush them on the next frame";
                }
            }
        }
    }
}

// A finite fresh sample beyond the float16 range: a plain store turns it into infinity (which
// the next blend then discards forever: the pixel sticks at the fresh sample); rrc_storeAmortized
// clamps it to the largest finite value.
TEST_F(StressRobustness, OutOfRangeSamplesStayFiniteWithStoreAmortized) {
    const std::string body = R"(
vec4 onMiss() { vec4 v = vec4(1.0e6, -1.0e6, 7.0e4, 1.0); return gl_FragCoord.x < 8.0 ? v : rrc_storeAmortized(v); }
vec4 onHit(rrc_Lookup l, vec4 cached) { return cached; }
)";
    for (GLenum format : {GL_RGBA16F, GL_R11F_G11F_B10F}) {
        Cache cache = Cache::create({.width = 16, .height = 4, .payloads = {{.format = format}}}).value();
        StressScene scene(cache, body);
        const Object objects[] = {{.model = kWall, .prevModel = kWall}};
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, Camera{}, objects));
        const auto image = readRGBA(cache.payload(0));
        const int channels = 3;
        std::printf("out of range %-18s plain store (1e6, -1e6, 7e4) -> (%g, %g, %g), rrc_storeAmortized -> (%g, %g, %g)\n",
                    formatName(format), double(image[0].r), double(image[0].g), double(image[0].b), double(image[8].r),
                    double(image[8].g), double(image[8].b));
        for (size_t i = 0; i < image.size(); ++i) {
            if (i % 16 < 8) continue;
            for (int c = 0; c < channels; ++c) {
                EXPECT_TRUE(std::isfinite(image[i][c])) << formatName(format);
            }
        }
    }
}

// Issue item i: lambda bounds, 1x1 caches, caches beyond GL_MAX_TEXTURE_SIZE, degenerate and
// non-finite matrices.
TEST_F(StressRobustness, EdgeArgumentsAreAcceptedOrRejectedWithTheirIds) {
    const glm::dmat4 view(1.0), projection = perspectiveReversedZ(1.0, 1.0, 0.1);
    {
        Cache cache = Cache::create({.width = 8, .height = 8}).value();
        for (float lambda : {0.0f, 0.5f, 0.999f}) {
            EXPECT_TRUE(cache.beginFrame({.view = view, .projection = projection, .lambda = lambda}).ok()) << lambda;
        }
        for (float lambda : {-0.1f, 1.0f, 1.5f, NAN, INFINITY, -INFINITY}) {
            LogCapture log;
            EXPECT_FALSE(cache.beginFrame({.view = view, .projection = projection, .lambda = lambda}).ok()) << lambda;
            EXPECT_TRUE(log.has(LogId::CacheBadArgument)) << lambda;
        }
        glm::dmat4 nanView(1.0), infProjection = projection, flat = projection;
        nanView[3][0] = NAN;
        infProjection[0][0] = INFINITY;
        flat[0][0] = 0.0;   // a "perspective" whose x scale is zero: singular
        const struct { const char* what; glm::dmat4 view, projection; } bad[] = {
            {"zero view", glm::dmat4(0.0), projection},        {"zero projection", view, glm::dmat4(0.0)},
            {"NaN view", nanView, projection},                 {"NaN projection", view, glm::dmat4(NAN)},
            {"infinite projection", view, infProjection},      {"identity projection", view, glm::dmat4(1.0)},
            {"singular projection", view, flat},
        };
        const uint64_t frameBefore = cache.frame();
        for (const auto& b : bad) {
            LogCapture log;
            EXPECT_FALSE(cache.beginFrame({.view = b.view, .projection = b.projection}).ok()) << b.what;
            EXPECT_TRUE(log.has(LogId::CacheNonFinite)) << b.what;
        }
        EXPECT_EQ(cache.frame(), frameBefore) << "a rejected frame leaves the cache unchanged";
    }
    // 1x1 caches in every flow.
    for (ControlFlow flow : {ControlFlow::OnePass, ControlFlow::TwoPass, ControlFlow::ThreePass}) {
        Cache cache = Cache::create({.width = 1, .height = 1, .payloads = {{.format = GL_RGBA32F}}}).value();
        CacheScene scene(cache);
        const Object objects[] = {{.model = kWall, .prevModel = kWall}};
        ASSERT_TRUE(scene.frame(cache, flow, Camera{}, objects));
        ASSERT_TRUE(scene.frame(cache, flow, Camera{}, objects));
        const Stats s = cache.finishStats();
        const glm::vec4 p = readRGBA(cache.payload(0))[0];
        std::printf("1x1 cache, flow %d: %llu hit of 1, payload (%g, %g, %g)\n", int(flow),
                    static_cast<unsigned long long>(s.hits), double(p.x), double(p.y), double(p.z));
        EXPECT_EQ(s.hits, 1u);
        EXPECT_NEAR(p.z, -10.0f, 1e-4f);
    }
    // Beyond GL_MAX_TEXTURE_SIZE.
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    for (auto [w, h] : {std::pair{maxSize + 1, 16}, std::pair{16, maxSize + 1}}) {
        LogCapture log;
        auto c = Cache::create({.width = w, .height = h});
        ASSERT_FALSE(c.ok());
        EXPECT_EQ(c.error().id, LogId::CacheTooLarge);
        EXPECT_NE(c.error().message.find("GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize)), std::string::npos) << c.error().message;
        EXPECT_TRUE(log.has(LogId::CacheTooLarge));
        std::printf("too large: \"%s\"\n", c.error().message.c_str());
    }
    {
        Cache cache = Cache::create({.width = 8, .height = 8}).value();
        LogCapture log;
        auto r = cache.resize(maxSize + 1, 8);
        EXPECT_FALSE(r.ok());
        EXPECT_EQ(r.error().id, LogId::CacheTooLarge);
        EXPECT_EQ(cache.width(), 8);   // unchanged and still usable
        EXPECT_TRUE(cache.beginFrame({.view = view, .projection = projection}).ok());
        EXPECT_TRUE(cache.render(ControlFlow::TwoPass, [](Pass) {}).ok());
    }
}

// Issue item j. The first frame after a cut or a resize is all misses and equals a fresh render
// (no ghost of the old view); field-of-view and near/far changes reproject with the cache-time
// projection, so hits stay correct.
TEST_F(StressRobustness, CutsResizesAndProjectionChangesKeepReprojectionCorrect) {
    constexpr int W = 96, H = 64;
    const glm::dmat4 box = quadAt({0.4, -0.2, -4}, {0.9, 0.7}), other = quadAt({-1.5, 1.0, -6}, {1.0, 1.0});
    const Object objects[] = {{.model = kWall, .prevModel = kWall, .id = 1}, {.model = box, .prevModel = box, .id = 2},
                              {.model = other, .prevModel = other, .id = 3}};
    auto fresh = [&](const Camera& camera, bool reversed, int w, int h) {
        Cache ref = Cache::create({.width = w, .height = h, .payloads = {{.format = GL_RGBA32F}}, .reversedZ = reversed}).value();
        CacheScene scene(ref);
        EXPECT_TRUE(scene.frame(ref, ControlFlow::TwoPass, camera, objects));
        return readRGBA(ref.payload(0));
    };
    const Camera a{.eye = {0.3, 0.1, 0.5}, .target = {0.2, 0.0, -1.0}};
    const Camera b{.eye = {-2.0, 1.0, 1.0}, .target = {1.0, -0.5, -8.0}, .fovy = 0.8};
    // Cut.
    {
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = GL_RGBA32F}}}).value();
        CacheScene scene(cache);
        for (int f = 0; f < 3; ++f) ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, a, objects));
        cache.invalidate();
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, b, objects));
        const Stats s = cache.finishStats();
        const bool identical = readRGBA(cache.payload(0)) == fresh(b, true, W, H);
        std::printf("cut: %llu of %d pixels invalid (all misses), image %s a fresh render\n",
                    static_cast<unsigned long long>(s.counts[int(Outcome::Invalid)]), W * H, identical ? "identical to" : "DIFFERS from");
        EXPECT_EQ(s.counts[int(Outcome::Invalid)], size_t(W * H));
        EXPECT_TRUE(identical);
    }
    // Resize (shrink and grow, each to another aspect).
    for (auto [w, h] : {std::pair{64, 48}, std::pair{120, 50}}) {
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = GL_RGBA32F}}}).value();
        CacheScene scene(cache);
        for (int f = 0; f < 2; ++f) ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, a, objects));
        ASSERT_TRUE(cache.resize(w, h).ok());
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, a, objects));
        const Stats first = cache.finishStats();
        const bool identical = readRGBA(cache.payload(0)) == fresh(a, true, w, h);
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, a, objects));
        const Stats second = cache.finishStats();
        std::printf("resize %dx%d -> %dx%d: first frame %llu of %d invalid, image %s a fresh render; next frame %llu hits\n", W,
                    H, w, h, static_cast<unsigned long long>(first.counts[int(Outcome::Invalid)]), w * h,
                    identical ? "identical to" : "DIFFERS from", static_cast<unsigned long long>(second.hits));
        EXPECT_EQ(first.counts[int(Outcome::Invalid)], size_t(w * h));
        EXPECT_TRUE(identical);
        EXPECT_EQ(second.hits, size_t(w * h));
    }
    // Projection changes between two frames from the same eye. Pixels within 2 pixels of a
    // silhouette in the fresh render are judged separately: there the bilinear depth mixes the
    // two surfaces and the relative tolerance admits a few percent of the other one (the same
    // happens for any camera motion, docs/stability.md).
    struct Change { const char* what; bool reversed; Camera from, to; };
    const Camera base{.eye = {0.3, 0.1, 0.5}, .target = {0.2, 0.0, -1.0}};
    auto with = [&](double fovy, double near, double far) { Camera c = base; c.fovy = fovy; c.near = near; c.far = far; return c; };
    const Change changes[] = {
        {"fov 1.0 -> 0.8 (zoom in)", true, with(1.0, 0.1, kInfiniteFar), with(0.8, 0.1, kInfiniteFar)},
        {"fov 1.0 -> 1.2 (zoom out)", true, with(1.0, 0.1, kInfiniteFar), with(1.2, 0.1, kInfiniteFar)},
        {"near 0.1 -> 0.5, far inf -> 200", true, with(1.0, 0.1, kInfiniteFar), with(1.0, 0.5, 200.0)},
        {"near 0.5 -> 0.05, far 200 -> 1e4", true, with(1.0, 0.5, 200.0), with(1.0, 0.05, 1e4)},
        {"standard: fov 1.0 -> 0.9, near 0.1 -> 0.3, far 100 -> 60", false, with(1.0, 0.1, 100.0), with(0.9, 0.3, 60.0)},
        {"standard: near 0.3 -> 0.01, far 60 -> 1e3", false, with(1.0, 0.3, 60.0), with(1.0, 0.01, 1e3)},
    };
    for (const Change& c : changes) {
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = GL_RGBA32F}}, .reversedZ = c.reversed}).value();
        CacheScene scene(cache);
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, c.from, objects));
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, c.to, objects));
        const auto outcomes = readUint(cache.outcomes());
        const auto image = readRGBA(cache.payload(0));
        const auto truth = fresh(c.to, c.reversed, W, H);
        // The source quad is identified by its world z (-4, -6 or -10) in the fresh render.
        auto interior = [&](int x, int y) {
            const float z = truth[size_t(y) * W + x].z;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int u = std::clamp(x + dx, 0, W - 1), v = std::clamp(y + dy, 0, H - 1);
                    if (std::abs(truth[size_t(v) * W + u].z - z) > 0.5f) return false;
                }
            return true;
        };
        // Where the cache saw each pixel's surface point (its texel coordinates in the old view).
        const double aspect = double(W) / H;
        auto source = [&](size_t i) {
            const glm::dvec4 clip = c.from.projection(aspect, c.reversed) * c.from.view() * glm::dvec4(glm::dvec3(truth[i]), 1.0);
            return (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(W, H);
        };
        // Classes: 0 interior, 1 near a silhouette, 2 within a texel of the old view's border
        // (bilinear clamps there: the border texel stands in for up to half a texel beyond it).
        size_t hits[3] = {}, visible = 0, visibleHits = 0;
        double worst[3] = {};
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const size_t i = size_t(y) * W + x;
                const glm::dvec2 t = source(i);
                const bool inside = t.x >= 1.0 && t.x <= W - 1.0 && t.y >= 1.0 && t.y <= H - 1.0;
                const bool seen = t.x >= 0.0 && t.x <= W && t.y >= 0.0 && t.y <= H;
                const int cls = !interior(x, y) ? 1 : !inside ? 2 : 0;
                const bool hit = outcomes[i] == uint32_t(Outcome::Hit);
                if (cls == 0 && seen) { ++visible; visibleHits += hit; }
                if (!hit) continue;
                ++hits[cls];
                worst[cls] = std::max(worst[cls], double(glm::length(glm::dvec3(image[i]) - glm::dvec3(truth[i]))));
            }
        const double rate = double(visibleHits) / double(std::max<size_t>(visible, 1));
        std::printf("projection change %s: %zu hits of %d pixels; interior: %zu of %zu previously seen pixels hit (%.4f), worst "
                    "error %.2e; near silhouettes: %zu hits, worst %.2e; last texel of the old view: %zu hits, worst %.2e "
                    "(world units)\n",
                    c.what, hits[0] + hits[1] + hits[2], W * H, visibleHits, visible, rate, worst[0], hits[1], worst[1],
                    hits[2], worst[2]);
        const double innerWorst = worst[0], edgeWorst = std::max(worst[1], worst[2]);
        EXPECT_GE(rate, 0.999) << c.what;
        EXPECT_LT(innerWorst, 1e-3) << c.what;
        EXPECT_LT(edgeWorst, 0.2) << c.what;   // a hit never takes a whole value from the other surface
    }
}

// Issue item k: an empty (default-constructed or moved-from) cache answers every call with
// CacheInvalidObject and no GL error; a wrong payload index gives 0 and CacheBadArgument.
TEST_F(StressRobustness, MisuseOfAnEmptyCacheIsADefinedError) {
    Cache live = Cache::create({.width = 16, .height = 8}).value();
    Cache moved = std::move(live);   // `live` is now moved-from
    Cache empty;
    Program anyProgram = createProgram();
    for (Cache* c : {&empty, &live}) {
        LogCapture log;
        bool drew = false;
        auto check = [&](const char* what, bool ok) {
            EXPECT_TRUE(ok) << what;
            EXPECT_TRUE(log.has(LogId::CacheInvalidObject)) << what;
            log.items.clear();
        };
        check("beginFrame", !c->beginFrame({.view = glm::dmat4(1.0), .projection = perspectiveReversedZ(1.0, 1.0, 0.1)}).ok());
        check("render", !c->render(ControlFlow::TwoPass, [&](Pass) { drew = true; }).ok() && !drew);
        check("resize", !c->resize(8, 8).ok());
        c->invalidate();
        check("invalidate", true);
        check("defines", c->defines().empty());
        check("payload", c->payload(0) == 0);
        check("previousPayload", c->previousPayload(0) == 0);
        check("depth", c->depth() == 0 && (c->previousDepth() == 0));
        check("outcomes", c->outcomes() == 0);
        check("framebuffer", c->framebuffer() == 0);
        check("desc", c->desc().width == 0);
        check("view", c->view().view == glm::dmat4(1.0) && c->cacheTimeView().projection == glm::dmat4(1.0));
        c->endFrame();
        check("endFrame", true);
        c->bindForLookup();
        check("bindForLookup", true);
        c->bindPayloads(0);
        check("bindPayloads", true);
        Texture t;
        c->visualize(t);
        check("visualize", !t);
        (void)c->drawMatrices(glm::dmat4(1.0), glm::dmat4(1.0));
        check("drawMatrices", true);
        c->setDrawUniforms(anyProgram.id(), DrawMatrices{});
        check("setDrawUniforms", true);
        EXPECT_FALSE(c->stats().valid);
        EXPECT_FALSE(c->finishStats().valid);
        EXPECT_EQ(c->width(), 0);
        EXPECT_FALSE(c->valid());
        EXPECT_EQ(checkGLErrors("empty cache calls"), 0);
    }
    // The moved-to cache works, and rejects bad payload indices.
    LogCapture log;
    EXPECT_NE(moved.payload(0), 0u);
    for (int index : {-1, 1, 4}) {
        EXPECT_EQ(moved.payload(index), 0u) << index;
        EXPECT_EQ(moved.previousPayload(index), 0u) << index;
    }
    EXPECT_TRUE(log.has(LogId::CacheBadArgument));
    size_t bad = 0;
    for (auto& i : log.items) bad += i.id == LogId::CacheBadArgument;
    EXPECT_EQ(bad, 6u);
    // Render before beginFrame.
    log.items.clear();
    EXPECT_FALSE(moved.render(ControlFlow::OnePass, [](Pass) {}).ok());
    EXPECT_TRUE(log.has(LogId::CacheBadArgument));
}

TEST_F(StressRobustness, InvalidDescriptorsAreRejected) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    GLint units = 0, bindings = 0;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
    glGetIntegerv(GL_MAX_UNIFORM_BUFFER_BINDINGS, &bindings);
    const struct { const char* what; CacheDesc desc; } bad[] = {
        {"zero width", {.width = 0, .height = 8}},
        {"zero height", {.width = 8, .height = 0}},
        {"negative size", {.width = -4, .height = 8}},
        {"no payload", {.width = 8, .height = 8, .payloads = {}}},
        {"five payloads", {.width = 8, .height = 8, .payloads = std::vector<PayloadDesc>(5)}},
        {"unsupported format", {.width = 8, .height = 8, .payloads = {{.format = GL_RGB8}}}},
        {"integer format filtered", {.width = 8, .height = 8, .payloads = {{.format = GL_R32UI, .resample = Resample::Bilinear}}}},
        {"depth in an RGBA8 payload", {.width = 8, .height = 8, .payloads = {{.format = GL_RGBA8}}, .depthInPayload = true}},
        {"zero depth tolerance", {.width = 8, .height = 8, .depthTolerance = 0.0f}},
        {"negative depth tolerance", {.width = 8, .height = 8, .depthTolerance = -0.01f}},
        {"NaN depth tolerance", {.width = 8, .height = 8, .depthTolerance = nan}},
        {"infinite depth tolerance", {.width = 8, .height = 8, .depthTolerance = inf}},
        {"NaN slope tolerance", {.width = 8, .height = 8, .slopeTolerance = nan}},
        {"negative slope tolerance", {.width = 8, .height = 8, .slopeTolerance = -1.0f}},
        {"NaN resample snap", {.width = 8, .height = 8, .resampleSnap = nan}},
        {"resample snap 0.5", {.width = 8, .height = 8, .resampleSnap = 0.5f}},
        {"negative max scale", {.width = 8, .height = 8, .maxScale = -1.0f}},
        {"NaN max scale", {.width = 8, .height = 8, .maxScale = nan}},
        {"negative texture unit", {.width = 8, .height = 8, .firstTextureUnit = -1}},
        {"texture unit past the last", {.width = 8, .height = 8, .firstTextureUnit = units}},
        {"negative uniform binding", {.width = 8, .height = 8, .uniformBinding = -1}},
        {"uniform binding past the last", {.width = 8, .height = 8, .uniformBinding = bindings}},
    };
    for (const auto& b : bad) {
        LogCapture log;
        auto c = Cache::create(b.desc);
        ASSERT_FALSE(c.ok()) << b.what;
        EXPECT_EQ(c.error().id, LogId::CacheInvalidDesc) << b.what;
        EXPECT_TRUE(log.has(LogId::CacheInvalidDesc)) << b.what;
        std::printf("invalid desc (%s): \"%s\"\n", b.what, c.error().message.c_str());
    }
    auto c = Cache::create({.width = 8, .height = 8, .payloads = {{.format = GL_RGB8}}});
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error().message.find("0x8051"), std::string::npos) << c.error().message;   // GL_RGB8, in hex
    Cache cache = Cache::create({.width = 8, .height = 8}).value();
    for (auto [w, h] : {std::pair{0, 8}, std::pair{8, -1}}) {
        LogCapture log;
        EXPECT_FALSE(cache.resize(w, h).ok());
        EXPECT_TRUE(log.has(LogId::CacheInvalidDesc));
    }
    EXPECT_EQ(cache.width(), 8);
}

// Issue item l: creating and destroying caches (with resizes, frames, stats and the
// visualisation) leaves no GL object behind, and the names they used are gone.
TEST_F(StressRobustness, CreatingAndDestroyingCachesLeavesNoGlObjects) {
    const long before = liveGlObjects();
    std::vector<GLuint> textures, framebuffers;
    const Object objects[] = {{.model = kWall, .prevModel = kWall}};
    for (int i = 0; i < 50; ++i) {
        Cache cache = Cache::create({.width = 16 + i % 7, .height = 12 + i % 5,
                                     .payloads = {{.format = GLenum(i % 2 ? GL_RGBA8 : GL_RGBA16F)}, {.format = GL_R32F}},
                                     .objectIds = i % 3 == 0, .age = i % 2 == 0}).value();
        for (int r = 0; r < 3; ++r) {
            ASSERT_TRUE(cache.resize(20 + r * 3 + i % 4, 10 + r * 5).ok());
            textures.push_back(cache.payload(0));
            textures.push_back(cache.previousDepth());
            framebuffers.push_back(cache.framebuffer());
        }
        if (i % 10 == 0) {   // frames, stats in flight and a visualisation, then destroyed
            CacheScene scene(cache);
            ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, Camera{}, objects));
            ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, Camera{}, objects));
            Texture vis;
            cache.visualize(vis);
        }
    }
    size_t stillTextures = 0, stillFramebuffers = 0;
    for (GLuint t : textures) stillTextures += glIsTexture(t) == GL_TRUE;
    for (GLuint f : framebuffers) stillFramebuffers += glIsFramebuffer(f) == GL_TRUE;
    std::printf("50 caches x 3 resizes: live rrc GL objects %ld before, %ld after; %zu of %zu texture names and %zu of %zu "
                "framebuffer names still exist\n", before, liveGlObjects(), stillTextures, textures.size(), stillFramebuffers,
                framebuffers.size());
    EXPECT_EQ(liveGlObjects(), before);
    EXPECT_EQ(stillTextures, 0u);
    EXPECT_EQ(stillFramebuffers, 0u);
}

// Issue item l: the GL state Cache::render leaves (docs/stability.md lists it), and that
// endFrame restores the program, texture unit 0 and storage buffer binding 0 it borrows.
TEST_F(StressRobustness, RenderLeavesTheDocumentedGlState) {
    Texture userColor = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(userColor.id(), 1, GL_RGBA8, 4, 4);
    Framebuffer user = createFramebuffer();
    glNamedFramebufferTexture(user.id(), GL_COLOR_ATTACHMENT0, userColor.id(), 0);
    Texture userTexture = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(userTexture.id(), 1, GL_RGBA8, 2, 2);
    Buffer userStorage = createBuffer();
    glNamedBufferStorage(userStorage.id(), 64, nullptr, 0);
    Program userProgram = program("stress/state.vert", "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n",
                                  "stress/state.frag", "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    const Object objects[] = {{.model = kWall, .prevModel = kWall}};
    for (bool reversed : {true, false})
        for (ControlFlow flow : {ControlFlow::OnePass, ControlFlow::TwoPass, ControlFlow::ThreePass}) {
            Cache cache = Cache::create({.width = 32, .height = 24, .reversedZ = reversed}).value();
            CacheScene scene(cache);
            ASSERT_TRUE(scene.frame(cache, flow, Camera{}, objects));   // so the next frame has a cache
            // The application's state before the frame.
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, user.id());
            glViewport(1, 2, 3, 4);
            glBindTextureUnit(0, userTexture.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, userStorage.id());
            glUseProgram(userProgram.id());
            const Camera camera;
            ASSERT_TRUE(cache.beginFrame({.view = camera.view(), .projection = camera.projection(32.0 / 24.0, reversed)}).ok());
            ASSERT_TRUE(cache.render(flow, [](Pass) {}).ok());
            GLint depthFunc = 0, drawFb = 0, clipDepth = 0, clipOrigin = 0, viewport[4] = {}, depthTexture = 0, block = 0;
            GLboolean depthMask = GL_FALSE, colorMask[4] = {}, depthTest = GL_TRUE, conditional = GL_TRUE;
            glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
            glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
            glGetBooleanv(GL_COLOR_WRITEMASK, colorMask);
            depthTest = glIsEnabled(GL_DEPTH_TEST);
            glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepth);
            glGetIntegerv(GL_CLIP_ORIGIN, &clipOrigin);
            glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFb);
            glGetIntegerv(GL_VIEWPORT, viewport);
            glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, GLuint(cache.desc().uniformBinding), &block);
            glActiveTexture(GLenum(GL_TEXTURE0 + cache.desc().firstTextureUnit));
            glGetIntegerv(GL_TEXTURE_BINDING_2D, &depthTexture);
            glActiveTexture(GL_TEXTURE0);
            conditional = glIsEnabled(GL_DEPTH_CLAMP);   // untouched: stays off
            GLint stencilFunc = 0, stencilRef = -1, stencilPass = 0, stencilFail = 0, stencilDepthFail = 0;
            glGetIntegerv(GL_STENCIL_FUNC, &stencilFunc);
            glGetIntegerv(GL_STENCIL_REF, &stencilRef);
            glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &stencilPass);
            glGetIntegerv(GL_STENCIL_FAIL, &stencilFail);
            glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &stencilDepthFail);
            EXPECT_EQ(glIsEnabled(GL_STENCIL_TEST), GL_FALSE);
            EXPECT_EQ(stencilFunc, GL_ALWAYS);
            EXPECT_EQ(stencilRef, 0);
            EXPECT_TRUE(stencilPass == GL_KEEP && stencilFail == GL_KEEP && stencilDepthFail == GL_KEEP);
            EXPECT_EQ(depthFunc, GL_LESS);
            EXPECT_EQ(depthMask, GL_TRUE);
            EXPECT_TRUE(colorMask[0] && colorMask[1] && colorMask[2] && colorMask[3]);
            EXPECT_EQ(depthTest, GL_FALSE);
            EXPECT_EQ(clipDepth, GL_NEGATIVE_ONE_TO_ONE);
            EXPECT_EQ(clipOrigin, GL_LOWER_LEFT);
            EXPECT_EQ(GLuint(drawFb), user.id());
            EXPECT_EQ(conditional, GL_FALSE);
            // Documented changes: the viewport is the cache's, the cache's units and block are bound.
            EXPECT_EQ(viewport[2], 32);
            EXPECT_EQ(viewport[3], 24);
            EXPECT_EQ(GLuint(depthTexture), cache.previousDepth());
            EXPECT_NE(block, 0);
            cache.endFrame();
            GLint programAfter = 0, unit0 = 0, storage0 = 0;
            glGetIntegerv(GL_CURRENT_PROGRAM, &programAfter);
            glGetIntegerv(GL_TEXTURE_BINDING_2D, &unit0);
            glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &storage0);
            EXPECT_EQ(GLuint(programAfter), userProgram.id());
            EXPECT_EQ(GLuint(unit0), userTexture.id());
            EXPECT_EQ(GLuint(storage0), userStorage.id());
            std::printf("state after render (%s, flow %d): depth func %s, depth mask %d, colour mask %d%d%d%d, depth test %d, "
                        "clip depth %s, stencil test %d func %s, draw framebuffer %s, viewport %d,%d,%d,%d (the cache's); after "
                        "endFrame program, unit 0 and SSBO 0 %s\n", reversed ? "reversed-Z" : "standard", int(flow), depthFunc == GL_LESS ? "GL_LESS" : "?",
                        depthMask, colorMask[0], colorMask[1], colorMask[2], colorMask[3], depthTest,
                        clipDepth == GL_NEGATIVE_ONE_TO_ONE ? "NEGATIVE_ONE_TO_ONE" : "ZERO_TO_ONE",
                        int(glIsEnabled(GL_STENCIL_TEST)), stencilFunc == GL_ALWAYS ? "GL_ALWAYS" : "?", GLuint(drawFb) == user.id() ? "the application's" : "CHANGED", viewport[0], viewport[1], viewport[2],
                        viewport[3],
                        GLuint(programAfter) == userProgram.id() && GLuint(unit0) == userTexture.id() &&
                                GLuint(storage0) == userStorage.id() ? "restored" : "CHANGED");
            glUseProgram(0);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
            glBindTextureUnit(0, 0);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
        }
}

// An application may delete the program it has current (ImGui does at shutdown): GL keeps it
// alive only until another program is made current, so the library must not restore its name.
TEST_F(StressRobustness, AProgramDeletedWhileCurrentIsNotRestored) {
    const Object objects[] = {{.model = kWall, .prevModel = kWall}};
    Cache cache = Cache::create({.width = 32, .height = 24}).value();
    CacheScene scene(cache);
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, Camera{}, objects));
    ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, Camera{}, objects));   // lookup + marking pass
    for (int step = 0; step < 2; ++step) {
        {
            Program doomed = program("stress/doomed.vert", "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n",
                                     "stress/doomed.frag", "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
            glUseProgram(doomed.id());
        }   // deleted while current
        if (step == 0) {
            Texture view;
            cache.visualize(view);
        } else {
            const Camera camera;
            ASSERT_TRUE(cache.beginFrame({.view = camera.view(), .projection = camera.projection(32.0 / 24.0, true)}).ok());
            ASSERT_TRUE(cache.render(ControlFlow::TwoPass, [](Pass) {}).ok());
            cache.endFrame();
        }
        GLint current = -1;
        glGetIntegerv(GL_CURRENT_PROGRAM, &current);
        EXPECT_EQ(current, 0) << (step == 0 ? "visualize" : "render + endFrame");
    }
    // The fixture fails the test on any GL error (GL_INVALID_VALUE from restoring a dead name).
}

} // namespace
} // namespace rrc::test
