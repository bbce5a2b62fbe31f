// Resampling over many frames of reuse: the blur of a sub-pixel pan against the repeated
// resampling bound of Yang et al. 2009 (issue item d), and a static camera whose reused image
// must stay bit-identical for 1000 frames (e).
#include "stress_scene.hpp"
#include "support/gl_test.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

namespace rrc::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Frequency response of one resampling step at fractional offset `alpha` for angular frequency
// `omega` (radians per pixel): bilinear |1 - a + a e^{iw}| (Yang et al. 2009, "Amortized
// supersampling", section 4), Catmull-Rom: sum of its four tap weights times e^{iwk}.
double bilinearGain(double alpha, double omega) {
    return std::abs(std::complex<double>(1.0 - alpha) + alpha * std::exp(std::complex<double>(0.0, omega)));
}
double bicubicGain(double alpha, double omega) {
    const double f = alpha;
    const double w[4] = {f * (-0.5 + f * (1.0 - 0.5 * f)), 1.0 + f * f * (-2.5 + 1.5 * f), f * (0.5 + f * (2.0 - 1.5 * f)),
                         f * f * (-0.5 + 0.5 * f)};
    std::complex<double> h = 0.0;
    for (int k = 0; k < 4; ++k) h += w[k] * std::exp(std::complex<double>(0.0, omega * (k - 1)));
    return std::abs(h);
}

class StressResample : public GLTest {};

const char* resampleName(Resample r) {
    return r == Resample::Nearest ? "nearest" : r == Resample::Bilinear ? "bilinear" : "bicubic";
}

// Issue item d: a fronto-parallel plane whose payload is cos(2 pi x / P) for periods of 16, 8 and
// 4 pixels (red, green, blue), the camera moving sideways by v pixels per frame; hits copy the
// cached value (nothing is refreshed). After N frames the amplitude left at each frequency is
// compared with the repeated-resampling bound gain(alpha, omega)^N, alpha = frac(v).
TEST_F(StressResample, SubPixelPanBlurMatchesTheRepeatedResamplingBound) {
    constexpr int W = 160, H = 8, kFrames = 16;
    const double periods[3] = {16.0, 8.0, 4.0};
    const Camera base{.eye = {0, 0, 0}, .target = {0, 0, -1}};
    const double depth = 10.0, pixel = 2.0 * depth * std::tan(base.fovy / 2.0) / H;   // world units per pixel
    const std::string body = R"(
// u_params.x: world units per pixel; the pattern is a function of the world x only.
vec4 pattern() {
    float px = v_world.x / u_params.x;
    return vec4(0.5 + 0.5 * cos(6.28318530718 * px / 16.0), 0.5 + 0.5 * cos(6.28318530718 * px / 8.0),
                0.5 + 0.5 * cos(6.28318530718 * px / 4.0), 1.0);
}
vec4 onMiss() { return pattern(); }
vec4 onHit(rrc_Lookup l, vec4 cached) { return cached; }
)";
    const glm::dmat4 wall = quadAt({0, 0, -depth}, {4000, 40});
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    // The measured region: pixels whose whole history stayed on screen (content moves left, new
    // content enters on the right), a whole number of periods wide.
    const int x0 = 8, x1 = 8 + 128;
    std::printf("sub-pixel pan, %d frames of reuse, RGBA32F payload; amplitude left (fresh = 1) measured vs bound "
                "gain^N, and rms error against the fresh image\n", kFrames);
    std::printf("%-5s %-9s %-6s %10s %10s %10s\n", "v px", "filter", "period", "measured", "bound", "rms");
    for (double v : {0.25, 0.5, 1.0}) {
        double amplitude[3][3] = {};   // [filter][period]
        for (Resample resample : {Resample::Nearest, Resample::Bilinear, Resample::Bicubic}) {
            Cache cache = Cache::create({.width = W, .height = H,
                                         .payloads = {{.format = GL_RGBA32F, .resample = resample}}}).value();
            StressScene scene(cache, body);
            scene.params.x = float(pixel);
            Camera camera = base;
            for (int f = 0; f <= kFrames; ++f) {
                camera.eye.x = camera.target.x = f * v * pixel;
                ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
            }
            const auto image = readRGBA(cache.payload(0));
            const auto outcomes = readUint(cache.outcomes());
            for (int c = 0; c < 3; ++c) {
                const double omega = 2.0 * kPi / periods[c];
                std::complex<double> dft = 0.0;
                double err2 = 0;
                int n = 0;
                for (int y = 0; y < H; ++y)
                    for (int x = x0; x < x1; ++x) {
                        const size_t i = size_t(y) * W + x;
                        EXPECT_EQ(outcomes[i], uint32_t(Outcome::Hit));
                        // Fresh value at this pixel: world x of the pixel centre in pixels.
                        const double px = camera.eye.x / pixel + (x + 0.5 - W / 2.0);
                        const double fresh = 0.5 + 0.5 * std::cos(omega * px);
                        dft += (double(image[i][c]) - 0.5) * std::exp(std::complex<double>(0.0, -omega * px));
                        err2 += (double(image[i][c]) - fresh) * (double(image[i][c]) - fresh);
                        ++n;
                    }
                const double measured = 2.0 * std::abs(dft) / n / 0.5;   // relative to the fresh amplitude 0.5
                const double alpha = v - std::floor(v);
                const double gain = resample == Resample::Bicubic ? bicubicGain(alpha, omega) : bilinearGain(alpha, omega);
                const double bound = resample == Resample::Nearest ? 1.0 : std::pow(gain, kFrames);
                std::printf("%-5.2f %-9s %-6.0f %10.4f %10.4f %10.4f\n", v, resampleName(resample), periods[c], measured,
                            bound, std::sqrt(err2 / n));
                amplitude[int(resample)][c] = measured;
                if (resample != Resample::Nearest) {
                    // Within 2% of the fresh amplitude, or 10% of the bound where the bound is small.
                    EXPECT_NEAR(measured, bound, std::max(0.02, 0.1 * bound))
                        << resampleName(resample) << " v " << v << " period " << periods[c];
                }
            }
        }
        for (int c = 0; c < 3; ++c) {
            if (v < 1.0) {
                EXPECT_GT(amplitude[int(Resample::Bicubic)][c], amplitude[int(Resample::Bilinear)][c]) << "v " << v;
            } else {
                EXPECT_NEAR(amplitude[int(Resample::Bilinear)][c], 1.0, 1e-3);   // whole-pixel shifts are copies
                EXPECT_NEAR(amplitude[int(Resample::Bicubic)][c], 1.0, 1e-3);
            }
        }
    }
}

// Issue item e: a static camera over 1000 frames (every frame a real lookup: objectsMoved stays
// true), hits copying the cached payload: the image must not drift, whatever the format and
// resampling.
TEST_F(StressResample, StaticCameraStaysBitIdenticalForAThousandFrames) {
    constexpr int W = 64, H = 48, kFrames = 1000;
    const std::string body = R"(
vec4 onMiss() {
    vec2 p = v_world.xy;
    return vec4(0.5 + 0.5 * sin(p.x * 3.1 + 0.3), 0.5 + 0.5 * sin(p.y * 2.3 + 1.1), 0.5 + 0.5 * sin((p.x + p.y) * 5.7), 1.0);
}
vec4 onHit(rrc_Lookup l, vec4 cached) { return cached; }
)";
    const glm::dmat4 wall = quadAt({0, 0, -10}, {40, 40}), box = quadAt({0.7, -0.3, -4}, {0.9, 0.6});
    const Object objects[] = {{.model = wall, .prevModel = wall, .id = 1}, {.model = box, .prevModel = box, .id = 2}};
    const Camera camera{.eye = {0.1, 0.2, 0.0}, .target = {0.13, 0.17, -1.0}};
    struct Case { GLenum format; Resample resample; float snap; };
    const float defaultSnap = CacheDesc{}.resampleSnap;
    const Case cases[] = {{GL_RGBA8, Resample::Bilinear, defaultSnap},   {GL_RGBA16F, Resample::Bilinear, defaultSnap},
                          {GL_RGBA32F, Resample::Bilinear, defaultSnap}, {GL_RGBA16F, Resample::Bicubic, defaultSnap},
                          {GL_RGBA16F, Resample::Nearest, defaultSnap},
                          // Without the snap (before the fix): reported, not judged.
                          {GL_RGBA16F, Resample::Bilinear, 0.0f}, {GL_RGBA32F, Resample::Bilinear, 0.0f},
                          {GL_RGBA16F, Resample::Bicubic, 0.0f}};
    for (const Case& c : cases) {
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = c.format, .resample = c.resample}},
                                     .resampleSnap = c.snap}).value();
        StressScene scene(cache, body);
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
        const auto first = readRGBA(cache.payload(0));
        auto previous = first;
        int changedFrames = 0, lastChange = 0;
        size_t hitsLast = 0;
        double drift = 0;
        for (int f = 1; f < kFrames; ++f) {
            ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
            auto image = readRGBA(cache.payload(0));
            if (image != previous) { ++changedFrames; lastChange = f; }
            if (f == kFrames - 1) {
                for (size_t i = 0; i < image.size(); ++i)
                    drift = std::max(drift, double(glm::length(image[i] - first[i])));
                hitsLast = cache.finishStats().hits;
            }
            previous = std::move(image);
        }
        std::printf("static camera %-11s %-8s snap %.5f: %d of %d frames changed the image (last at frame %d), "
                    "max |frame %d - frame 0| = %.3g, %zu/%d hits in the last frame\n",
                    formatName(c.format), resampleName(c.resample), double(c.snap), changedFrames, kFrames - 1, lastChange,
                    kFrames - 1, drift, hitsLast, W * H);
        EXPECT_EQ(hitsLast, size_t(W * H));
        if (c.snap == 0.0f) continue;
        EXPECT_LT(lastChange, kFrames / 2) << "still changing after convergence";
        EXPECT_EQ(changedFrames, 0) << "reuse of a static view should copy the cache bit for bit";
    }
}

// The float noise in the reprojected position of a static view, against CacheDesc::resampleSnap
// (a snap distance must exceed it, or static views drift again at that size).
TEST_F(StressResample, ReprojectionNoiseOfAStaticViewIsBelowTheSnapDistance) {
    const std::string body = R"(
vec4 onMiss() { return vec4(0.0); }
vec4 onHit(rrc_Lookup l, vec4 cached) { return vec4(l.uv * rrc_cacheSize.xy - gl_FragCoord.xy, 1.0, 1.0); }
)";
    const glm::dmat4 wall = quadAt({0, 0, -10}, {1e5, 40}), box = quadAt({0.7, -0.3, -4}, {0.9, 0.6});
    const Object objects[] = {{.model = wall, .prevModel = wall, .id = 1}, {.model = box, .prevModel = box, .id = 2}};
    const Camera camera{.eye = {0.1, 0.2, 0.0}, .target = {0.13, 0.17, -1.0}};
    for (auto [w, h] : {std::pair{64, 48}, std::pair{1024, 768}, std::pair{4096, 256}, std::pair{8192, 64}}) {
        Cache cache = Cache::create({.width = w, .height = h, .payloads = {{.format = GL_RGBA32F, .resample = Resample::Nearest}}}).value();
        StressScene scene(cache, body);
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
        double worst = 0;
        size_t hits = 0;
        for (const auto& p : readRGBA(cache.payload(0))) {
            if (p.z != 1.0f) continue;
            ++hits;
            worst = std::max({worst, std::abs(double(p.x)), std::abs(double(p.y))});
        }
        std::printf("static view %5dx%-4d: max |reprojected position - pixel centre| = %.3g texels over %zu hits "
                    "(snap distance %.3g)\n", w, h, worst, hits, double(CacheDesc{}.resampleSnap));
        EXPECT_GT(hits, size_t(w) * h / 2);
        EXPECT_LT(worst, CacheDesc{}.resampleSnap) << w << "x" << h;   // about 1 ulp of the texel coordinate
    }
}

} // namespace
} // namespace rrc::test
