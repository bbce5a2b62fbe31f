// The recursive filter under the payload formats' precision: the dead zone a plain store leaves
// and rrc_storeAmortized removes (issue item a), the noise variance ratio (b), the step response
// (c), and the extreme weights lambda = 0 and 0.999 (i). Every test prints its figures.
#include "stress_scene.hpp"
#include "support/gl_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace rrc::test {
namespace {

// A GLSL float array literal.
std::string glslArray(const std::vector<float>& values) {
    std::string s = "float[" + std::to_string(values.size()) + "](";
    for (size_t i = 0; i < values.size(); ++i) {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%s%.9g", i ? ", " : "", double(values[i]));
        s += buf;
    }
    if (s.find('.') == std::string::npos) s += ".0";
    return s + ")";
}

// Spacing of representable values of `format`'s channel `c` around `v` (> 0).
double ulpAt(GLenum format, int c, double v) {
    auto floatUlp = [&](int mantissaBits) {
        const int e = std::max(static_cast<int>(std::floor(std::log2(v))), -14);
        return std::ldexp(1.0, e - mantissaBits);
    };
    switch (format) {
    case GL_RGBA8: return 1.0 / 255.0;
    case GL_RGB10_A2: return c == 3 ? 1.0 / 3.0 : 1.0 / 1023.0;
    case GL_RGBA16F: case GL_RG16F: case GL_R16F: return floatUlp(10);
    case GL_R11F_G11F_B10F: return floatUlp(c == 2 ? 5 : 6);
    default: return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(v))) - 23);
    }
}

// Channels a format stores (1..4).
int channels(GLenum format) {
    switch (format) {
    case GL_R16F: case GL_R32F: return 1;
    case GL_RG16F: case GL_RG32F: return 2;
    case GL_R11F_G11F_B10F: return 3;
    default: return 4;
    }
}

const GLenum kAmortizationFormats[] = {GL_RGBA8,   GL_RGB10_A2, GL_RGBA16F, GL_RG16F, GL_R16F,
                                       GL_R11F_G11F_B10F, GL_RGBA32F, GL_RG32F, GL_R32F};

class StressBlend : public GLTest {};

TEST_F(StressBlend, StoreRoundingProbeReportsEachFormatsRounding) {
    for (GLenum format : kAmortizationFormats) {
        auto r = probeStoreRounding(format);
        ASSERT_TRUE(r.ok()) << formatName(format);
        std::printf("store rounding %-18s %s\n", formatName(format), std::string(storeRoundingName(r.value())).c_str());
        if (format == GL_RGBA32F || format == GL_RG32F || format == GL_R32F) {
            EXPECT_EQ(r.value(), StoreRounding::Exact);
        } else {
            EXPECT_NE(r.value(), StoreRounding::Exact);
        }
    }
    EXPECT_FALSE(probeStoreRounding(GL_RGB8).ok());
}

// Issue item a: C = rrc_blend(C, s) with constant s from C = 0, 400 frames, pure recursive filter
// (the age argument is saturated so the weight is lambda). Columns: (lambda, s); bottom half a
// plain store, top half rrc_storeAmortized.
TEST_F(StressBlend, RecursiveFilterDeadZoneIsRemovedByStochasticRounding) {
    const std::vector<float> lambdas = {0.6f, 0.6f, 0.9f, 0.9f, 0.95f, 0.95f};
    const std::vector<float> targets = {0.5f, 0.9f, 0.5f, 0.9f, 0.5f, 0.9f};
    constexpr int kCellW = 32, kH = 128, kFrames = 400;
    const int W = kCellW * static_cast<int>(lambdas.size());
    const std::string body = "const float kLambda[6] = " + glslArray(lambdas) + ";\n" +
                             "const float kTarget[6] = " + glslArray(targets) + ";\n" + R"(
int cell() { return min(int(gl_FragCoord.x) / 32, 5); }
vec4 onMiss() { return vec4(0.0); }
vec4 onHit(rrc_Lookup l, vec4 cached) {
    int c = cell();
    vec4 v = rrc_blend(cached, vec4(kTarget[c]), 65535u, kLambda[c]);
    return gl_FragCoord.y >= 64.0 ? rrc_storeAmortized(v) : v;
}
)";
    const glm::dmat4 wall = quadAt({0, 0, -10}, {40, 40});
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    std::printf("dead zone after %d frames from C = 0: bias = mean(C - s) in 1/255 and in ulps of the format "
                "at s; rms = per-pixel rms error in 1/255\n", kFrames);
    std::printf("%-18s %-11s %-6s %-5s %-3s %12s %10s %12s %10s %8s\n", "format", "rounding", "lambda", "s", "ch",
                "plain/255", "plain ulp", "dither/255", "dither ulp", "rms/255");
    double worstDithered = 0, worstPlain = 0;
    for (GLenum format : kAmortizationFormats) {
        Cache cache = Cache::create({.width = W, .height = kH,
                                     .payloads = {{.format = format, .resample = Resample::Nearest}}}).value();
        StressScene scene(cache, body);
        const auto rounding = probeStoreRounding(format);
        ASSERT_TRUE(rounding.ok());
        Camera camera;
        for (int f = 0; f <= kFrames; ++f) ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
        const auto image = readRGBA(cache.payload(0));
        const int n = channels(format);
        for (size_t cell = 0; cell < lambdas.size(); ++cell) {
            for (int c = 0; c < std::min(n, 3); ++c) {
                if (c == 1 || (c == 2 && format != GL_R11F_G11F_B10F)) continue;   // red, and 11/11/10's 10-bit blue
                const double s = targets[cell];
                double sum[2] = {0, 0}, sum2[2] = {0, 0};
                size_t count[2] = {0, 0};
                for (int y = 0; y < kH; ++y)
                    for (int x = int(cell) * kCellW; x < int(cell + 1) * kCellW; ++x) {
                        const int half = y >= kH / 2;
                        const double e = double(image[size_t(y) * W + x][c]) - s;
                        sum[half] += e;
                        sum2[half] += e * e;
                        ++count[half];
                    }
                const double plain = sum[0] / double(count[0]), dithered = sum[1] / double(count[1]);
                const double rms = std::sqrt(sum2[1] / double(count[1]));
                const double ulp = ulpAt(format, c, s);
                std::printf("%-18s %-11s %-6.2f %-5.2f %-3s %+12.3f %+10.2f %+12.4f %+10.3f %8.3f\n", formatName(format),
                            std::string(storeRoundingName(rounding.value())).c_str(), double(lambdas[cell]), s,
                            c == 0 ? "R" : "B", plain * 255.0, plain / ulp, dithered * 255.0, dithered / ulp, rms * 255.0);
                worstDithered = std::max(worstDithered, std::abs(dithered) * 255.0);
                worstPlain = std::max(worstPlain, std::abs(plain) * 255.0);
                EXPECT_LE(std::abs(dithered) * 255.0, 0.5) << formatName(format) << " lambda " << lambdas[cell] << " s " << s;
            }
        }
    }
    std::printf("worst |bias|: plain store %.3f/255, rrc_storeAmortized %.4f/255\n", worstPlain, worstDithered);
}

// The values rrc_storeAmortized produces are representable: what the store wrote equals what
// the shader computed (kept in an RGBA32F target beside it), whatever the store's rounding.
TEST_F(StressBlend, StochasticRoundingProducesRepresentableValues) {
    const char* vertex = R"(#version 450 core
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
    const char* fragment = R"(#version 450 core
#include <rrc/blend.glsl>
layout(location = 0) out vec4 o_stored;
layout(location = 1) out vec4 o_exact;
void main() {
    // Rows 0-7: from half denormals (2^-20) past the half range (2^16.5), negative in rows 0-3.
    // Rows 8-23: 1024 values evenly over [0, 1] (every UNORM code range).
    vec2 p = gl_FragCoord.xy;
    float m = exp2(mix(-20.0, 16.5, p.x / 64.0)) * (p.y < 4.0 ? -1.0 : 1.0) * (1.0 + 0.37 * fract(p.y * 0.618));
    if (p.y >= 8.0) m = (floor(p.x) + 64.0 * floor(p.y - 8.0) + 0.37) / 1024.0;
    vec4 r = rrc_storeAmortized(vec4(m, m * 0.3, min(m * 1.7, 1.0), m * 0.01));
    o_stored = r;
    o_exact = r;
}
)";
    constexpr int W = 64, H = 24;
    for (GLenum format : kAmortizationFormats) {
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = format}}}).value();
        Program p = program("stress/fill.vert", vertex, "stress/fill.frag", fragment, cache.defines());
        Texture stored = createTexture(GL_TEXTURE_2D), exact = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(stored.id(), 1, format, W, H);
        glTextureStorage2D(exact.id(), 1, GL_RGBA32F, W, H);
        Framebuffer fb = createFramebuffer();
        glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT0, stored.id(), 0);
        glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT1, exact.id(), 0);
        const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fb.id(), 2, buffers);
        VertexArray vao = createVertexArray();
        cache.bindForLookup();   // the cache block (frame number for the dither)
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb.id());
        glViewport(0, 0, W, H);
        glUseProgram(p.id());
        glBindVertexArray(vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        const auto a = readRGBA(stored.id()), b = readRGBA(exact.id());
        const bool unorm = format == GL_RGBA8 || format == GL_RGB10_A2;
        const bool isUnsigned = unorm || format == GL_R11F_G11F_B10F;
        size_t compared = 0, different = 0;
        for (size_t i = 0; i < a.size(); ++i)
            for (int c = 0; c < channels(format); ++c) {
                if (isUnsigned && b[i][c] < 0.0f) continue;   // stored as 0 by definition
                ++compared;
                if (unorm) {
                    const double n = format == GL_RGBA8 ? 255.0 : (c == 3 ? 3.0 : 1023.0);
                    different += std::lround(double(b[i][c]) * n - 0.25) != std::lround(double(a[i][c]) * n);
                } else {
                    different += a[i][c] != b[i][c];
                }
            }
        std::printf("representable %-18s %zu channel values compared, %zu differ from the computed value\n",
                    formatName(format), compared, different);
        EXPECT_EQ(different, 0u) << formatName(format);
    }
}

// Issue item b: variance of the filtered noise / variance of the noise = (1 - lambda)/(1 + lambda),
// with the age-aware weight and rrc_storeAmortized, per quadrant lambda.
TEST_F(StressBlend, NoiseVarianceRatioIsOneMinusLambdaOverOnePlusLambda) {
    const std::vector<float> lambdas = {0.4f, 0.6f, 0.75f, 0.9f};
    constexpr int kSize = 256, kFrames = 90;
    const std::string body = "const float kLambda[4] = " + glslArray(lambdas) + ";\n" + R"(
float lambdaHere() { ivec2 q = ivec2(gl_FragCoord.xy) / 128; return kLambda[q.y * 2 + q.x]; }
vec4 noise() { return vec4(rrc_hashToUnit(rrc_hash(uvec3(uvec2(gl_FragCoord.xy), u_frame + 17u)))); }
vec4 onMiss() { return rrc_storeAmortized(rrc_firstSample(noise())); }
vec4 onHit(rrc_Lookup l, vec4 cached) { return rrc_storeAmortized(rrc_blend(cached, noise(), l.age, lambdaHere())); }
)";
    const glm::dmat4 wall = quadAt({0, 0, -10}, {40, 40});
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    for (GLenum format : {GL_RGBA32F, GL_RGBA16F, GL_RGBA8, GL_R11F_G11F_B10F}) {
        Cache cache = Cache::create({.width = kSize, .height = kSize,
                                     .payloads = {{.format = format, .resample = Resample::Nearest}}, .age = true}).value();
        StressScene scene(cache, body);
        Camera camera;
        for (int f = 0; f < kFrames; ++f) ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
        const auto image = readRGBA(cache.payload(0));
        for (int q = 0; q < 4; ++q) {
            double sum = 0, sum2 = 0;
            size_t n = 0;
            for (int y = (q / 2) * 128; y < (q / 2 + 1) * 128; ++y)
                for (int x = (q % 2) * 128; x < (q % 2 + 1) * 128; ++x) {
                    const double v = image[size_t(y) * kSize + x].r;
                    sum += v;
                    sum2 += v * v;
                    ++n;
                }
            const double mean = sum / double(n), variance = sum2 / double(n) - mean * mean;
            const double lambda = lambdas[size_t(q)], expected = (1.0 / 12.0) * (1.0 - lambda) / (1.0 + lambda);
            std::printf("variance %-18s lambda %.2f: mean %.4f, variance %.6f, expected %.6f, ratio %.3f\n",
                        formatName(format), lambda, mean, variance, expected, variance / expected);
            EXPECT_NEAR(mean, 0.5, 0.01) << formatName(format) << " lambda " << lambda;
            // 16384 samples per quadrant: the variance estimate's sampling error is ~1.1%.
            EXPECT_NEAR(variance / expected, 1.0, 0.05) << formatName(format) << " lambda " << lambda;
        }
    }
}

// Issue item c: after a step of the input from 0.2 to 0.8, |C - s| falls below tol * step within
// ceil(ln tol / ln lambda) frames (+1 for rounding).
TEST_F(StressBlend, StepResponseSettlesWithinLogTolOverLogLambda) {
    const std::vector<float> lambdas = {0.6f, 0.9f, 0.95f};
    constexpr int kCellW = 32, kH = 64, kFrames = 110;
    const int W = kCellW * 3;
    const double from = 0.2, to = 0.8, step = to - from;
    const std::string body = "const float kLambda[3] = " + glslArray(lambdas) + ";\n" + R"(
vec4 onMiss() { return vec4(u_params.x); }
vec4 onHit(rrc_Lookup l, vec4 cached) {
    vec4 v = rrc_blend(cached, vec4(u_params.y), 65535u, kLambda[min(int(gl_FragCoord.x) / 32, 2)]);
    return gl_FragCoord.y >= 32.0 ? rrc_storeAmortized(v) : v;
}
)";
    const glm::dmat4 wall = quadAt({0, 0, -10}, {40, 40});
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    std::printf("step response %.1f -> %.1f: frames until |C - s| <= tol * %.1f for good (mean over the cell; "
                "RGBA32F: every pixel), bound ceil(ln tol / ln lambda)\n", from, to, step);
    for (GLenum format : {GL_RGBA32F, GL_RGBA16F, GL_RGBA8}) {
        Cache cache = Cache::create({.width = W, .height = kH, .payloads = {{.format = format, .resample = Resample::Nearest}}}).value();
        StressScene scene(cache, body);
        scene.params = glm::vec4(float(from), float(from), 0, 0);
        Camera camera;
        ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));   // miss: C = 0.2
        scene.params.y = float(to);
        // error[half][cell][frame]: mean and max |C - s| after `frame + 1` blends.
        std::vector<double> meanError[2][3], maxError[2][3];
        for (int f = 0; f < kFrames; ++f) {
            ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
            const auto image = readRGBA(cache.payload(0));
            for (int half = 0; half < 2; ++half)
                for (int cell = 0; cell < 3; ++cell) {
                    double sum = 0, worst = 0;
                    for (int y = half * 32; y < half * 32 + 32; ++y)
                        for (int x = cell * kCellW; x < (cell + 1) * kCellW; ++x) {
                            const double e = double(image[size_t(y) * W + x].r) - to;
                            sum += e;
                            worst = std::max(worst, std::abs(e));
                        }
                    meanError[half][cell].push_back(std::abs(sum / (32.0 * kCellW)));
                    maxError[half][cell].push_back(worst);
                }
        }
        // First number of blends after which the error stays within tol * step; -1: never.
        auto settle = [&](const std::vector<double>& e, double tol) {
            int last = -1;
            for (int i = 0; i < int(e.size()); ++i)
                if (e[size_t(i)] > tol * step) last = i;
            return last + 1 >= int(e.size()) ? -1 : last + 2;
        };
        for (int cell = 0; cell < 3; ++cell)
            for (double tol : {0.05, 0.01}) {
                const double lambda = lambdas[size_t(cell)];
                const int bound = static_cast<int>(std::ceil(std::log(tol) / std::log(lambda)));
                const bool exact = format == GL_RGBA32F;
                const int plain = settle(exact ? maxError[0][cell] : meanError[0][cell], tol);
                const int dithered = settle(exact ? maxError[1][cell] : meanError[1][cell], tol);
                std::printf("step %-11s lambda %.2f tol %.2f: bound %3d, plain store %3d, rrc_storeAmortized %3d%s\n",
                            formatName(format), lambda, tol, bound, plain, dithered, plain < 0 ? " (plain: never)" : "");
                EXPECT_GE(dithered, 0) << formatName(format);
                EXPECT_LE(dithered, bound + 1) << formatName(format) << " lambda " << lambda << " tol " << tol;
                if (exact) {
                    EXPECT_LE(plain, bound + 1);
                    EXPECT_GE(plain, bound - 1);   // and not faster than the filter allows
                }
            }
    }
}

// Issue item i: lambda = 0 keeps only the fresh sample; lambda = 0.999 with the age-aware weight
// is the exact running mean over the whole history. Both against the CPU mirror of the hash.
TEST_F(StressBlend, LambdaZeroAndNearOneWork) {
    constexpr int W = 48, H = 32, kFrames = 24;
    const glm::dmat4 wall = quadAt({0, 0, -10}, {40, 40});
    const Object objects[] = {{.model = wall, .prevModel = wall}};
    auto noise = [](int x, int y, uint32_t frame) {
        return static_cast<float>(hash3(uint32_t(x), uint32_t(y), frame + 17u) >> 8) * (1.0f / 16777216.0f);
    };
    for (float lambda : {0.0f, 0.999f}) {
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = GL_RGBA32F, .resample = Resample::Nearest}},
                                     .age = true}).value();
        CacheScene scene(cache, Shading::Amortized);
        Camera camera;
        std::vector<double> mean(size_t(W) * H, 0.0);
        double worst = 0;
        for (int f = 0; f < kFrames; ++f) {
            ASSERT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects, {.lambda = lambda}));
            const auto frame = static_cast<uint32_t>(cache.frame());
            const auto image = readRGBA(cache.payload(0));
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const size_t i = size_t(y) * W + x;
                    mean[i] += (noise(x, y, frame) - mean[i]) / double(f + 1);
                    const double expected = lambda == 0.0f ? double(noise(x, y, frame)) : mean[i];
                    worst = std::max(worst, std::abs(double(image[i].y) - expected));
                }
        }
        std::printf("lambda %.3f over %d frames: worst |C - expected| = %.3g (expected: %s)\n", double(lambda), kFrames,
                    worst, lambda == 0.0f ? "the fresh sample" : "the running mean of all samples");
        if (lambda == 0.0f) {
            EXPECT_EQ(worst, 0.0);
        } else {
            EXPECT_LT(worst, 1e-5);
        }
    }
}

} // namespace
} // namespace rrc::test
