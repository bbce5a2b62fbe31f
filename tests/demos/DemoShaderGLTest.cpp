// The common GLSL on a headless context (backend from RRC_GL_BACKEND, default egl): noise is zero
// on the lattice and bounded, marble/wood compile at 1 and 5 octaves (the 5-octave cost is
// printed, not asserted), Blinn-Phong splits into view-independent + specular parts, and the
// full-screen pass covers the viewport.
#include <common/fullscreen.hpp>
#include <common/target.hpp>

#include <rrc/context.hpp>
#include <rrc/debug.hpp>
#include <rrc/image.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <optional>
#include <vector>

namespace rrc::demo::test {
namespace {

class DemoShaderGL : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        const char* env = std::getenv("RRC_GL_BACKEND");
        auto backend = parseBackend(env && *env ? env : "egl");
        ASSERT_TRUE(backend.ok());
        auto created = Context::create({.backend = backend.value(), .width = 16, .height = 16, .visible = false});
        ASSERT_TRUE(created.ok()) << created.error().message;
        context_.emplace(std::move(created).value());
    }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        ASSERT_TRUE(context_.has_value());
        checkGLErrors("before test");
        resetDebugCounters();
        library_.add(commonShaders());
    }
    void TearDown() override {
        EXPECT_EQ(checkGLErrors("end of test"), 0);
        EXPECT_EQ(debugCounters().debugErrors, 0);
    }

    // Renders `body` (a fragment shader main() writing o_value) over a w x h RGBA32F target.
    std::vector<float> render(const std::string& body, int w, int h, std::vector<Define> defines = {}) {
        library_.add("test/" + std::to_string(++shaders_) + ".frag",
                     "#version 450 core\n#include <common/shaders/marble.glsl>\n#include <common/shaders/lighting.glsl>\n"
                     "in vec2 demo_uv;\nlayout(location = 0) out vec4 o_value;\n" + body);
        auto pass = FullscreenPass::create(library_, "test/" + std::to_string(shaders_) + ".frag", std::move(defines));
        EXPECT_TRUE(pass.ok());
        auto target = RenderTarget::create({.width = w, .height = h, .colorFormats = {GL_RGBA32F}, .depthFormat = 0});
        EXPECT_TRUE(target.ok());
        if (!pass.ok() || !target.ok()) return {};
        target.value().bind();
        pass.value().draw();
        std::vector<float> pixels(static_cast<size_t>(w) * h * 4);
        glGetTextureImage(target.value().color(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(float)), pixels.data());
        return pixels;
    }

    static inline std::optional<Context> context_;
    ShaderLibrary library_;
    int shaders_ = 0;
};

TEST_F(DemoShaderGL, NoiseIsZeroOnTheLatticeAndBounded) {
    const auto lattice = render("void main() { ivec2 p = ivec2(gl_FragCoord.xy) - 32;\n"
                                "  o_value = vec4(demo_perlin(vec3(p, p.x - p.y)), demo_perlin(vec3(p.y, 7, p.x)), 0, 1); }", 64, 64);
    ASSERT_FALSE(lattice.empty());
    for (size_t i = 0; i < lattice.size(); i += 4) {
        ASSERT_EQ(lattice[i], 0.0f);
        ASSERT_EQ(lattice[i + 1], 0.0f);
    }
    const auto field = render("void main() { o_value = vec4(demo_perlin(vec3(gl_FragCoord.xy * 0.173, 2.71)),\n"
                              "  demo_fbm(vec3(gl_FragCoord.xy * 0.05, 0.5)), demo_turbulence(vec3(gl_FragCoord.xy * 0.05, 0.5)), 1); }", 128, 128);
    double sum = 0.0, lo = 1e9, hi = -1e9;
    for (size_t i = 0; i < field.size(); i += 4) {
        sum += field[i];
        lo = std::min<double>(lo, field[i]);
        hi = std::max<double>(hi, field[i]);
        EXPECT_LE(std::abs(field[i + 1]), 1.0f);
        EXPECT_GE(field[i + 2], 0.0f);
    }
    const double mean = sum / (field.size() / 4);
    std::printf("perlin over 128x128 samples: min %.3f max %.3f mean %.4f\n", lo, hi, mean);
    EXPECT_GE(lo, -1.05);
    EXPECT_LE(hi, 1.05);
    EXPECT_LT(lo, -0.4);
    EXPECT_GT(hi, 0.4);
    EXPECT_LT(std::abs(mean), 0.05);
}

TEST_F(DemoShaderGL, SeedSelectsAnotherField) {
    const std::string body = "void main() { o_value = vec4(demo_perlin(vec3(gl_FragCoord.xy * 0.3, 0.5))); }";
    const auto a = render(body, 16, 16), b = render(body, 16, 16, {{"RRC_DEMO_NOISE_SEED", "1u"}}), c = render(body, 16, 16);
    EXPECT_EQ(a, c);
    EXPECT_NE(a, b);
}

TEST_F(DemoShaderGL, BlinnPhongSplitsViewIndependentAndSpecular) {
    const auto v = render(R"(void main() {
        demo_Light light = demo_Light(vec3(0, 1, 0), vec3(1.0), vec3(0.1));
        vec3 toEye = gl_FragCoord.x < 1.0 ? vec3(0, 1, 0) : vec3(1, 0, 0);
        vec3 n = gl_FragCoord.x < 2.0 ? vec3(0, 1, 0) : vec3(0, -1, 0);
        demo_Shading s = demo_blinnPhong(vec3(0.5), n, toEye, light, vec3(1.0), 16.0);
        o_value = vec4(s.viewIndependent.r, s.specular.r, demo_total(s).r, 1);
    })", 3, 1);
    ASSERT_EQ(v.size(), 12u);
    EXPECT_NEAR(v[0], 0.55f, 1e-6);           // albedo * (ambient + N.L)
    EXPECT_NEAR(v[1], 1.0f, 1e-6);            // H = N: full highlight
    EXPECT_NEAR(v[2], 1.55f, 1e-6);
    EXPECT_NEAR(v[4], 0.55f, 1e-6);           // view-independent part does not move with the eye
    EXPECT_NEAR(v[5], std::pow(std::sqrt(0.5f), 16.0f), 1e-6);
    EXPECT_NEAR(v[8], 0.05f, 1e-6);           // facing away: ambient only, no specular
    EXPECT_EQ(v[9], 0.0f);
}

TEST_F(DemoShaderGL, MarbleAndWoodCompileAtOneAndFiveOctavesAndFiveCostMore) {
    constexpr int w = 1024, h = 768, warmup = 5, frames = 20;
    auto timeShader = [&](const std::string& material, int octaves) {
        library_.add("test/material.frag",
                     "#version 450 core\n#include <common/shaders/marble.glsl>\nin vec2 demo_uv;\n"
                     "layout(location = 0) out vec4 o_value;\nvoid main() { vec3 p = vec3(demo_uv * 8.0, 0.5);\n"
                     "  o_value = vec4(" + material + "(p), 1.0); }");
        auto pass = FullscreenPass::create(library_, "test/material.frag", {{"RRC_DEMO_OCTAVES", std::to_string(octaves)}});
        EXPECT_TRUE(pass.ok()) << material << " at " << octaves << " octaves";
        auto target = RenderTarget::create({.width = w, .height = h, .depthFormat = 0});
        if (!pass.ok() || !target.ok()) return 0.0;
        target.value().bind();
        std::vector<double> ms;
        for (int i = 0; i < warmup + frames; ++i) {
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            pass.value().draw();
            glFinish();
            if (i >= warmup) ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        std::sort(ms.begin(), ms.end());
        return ms[ms.size() / 2];
    };
    for (const std::string material : {"demo_marble", "demo_wood"}) {
        const double one = timeShader(material, 1), five = timeShader(material, 5);
        std::printf("%s %dx%d on %s: 1 octave %.2f ms, 5 octaves %.2f ms (median of %d, glFinish-timed)\n",
                    material.c_str(), w, h, context_->renderer().c_str(), one, five, frames);
        EXPECT_GT(one, 0.0);
        EXPECT_GT(five, 0.0);
    }
}

TEST_F(DemoShaderGL, BlitterCopiesATexture) {
    auto source = RenderTarget::create({.width = 8, .height = 8, .colorFormats = {GL_RGBA32F}, .depthFormat = 0});
    auto dest = RenderTarget::create({.width = 8, .height = 8, .colorFormats = {GL_RGBA32F}, .depthFormat = 0});
    auto blitter = Blitter::create(library_);
    ASSERT_TRUE(source.ok() && dest.ok() && blitter.ok());
    const float colour[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    glClearTexImage(source.value().color(), 0, GL_RGBA, GL_FLOAT, colour);
    dest.value().bind();
    blitter.value().draw(source.value().color(), 2.0f);
    std::vector<float> px(8 * 8 * 4);
    glGetTextureImage(dest.value().color(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(px.size() * sizeof(float)), px.data());
    for (size_t i = 0; i < px.size(); i += 4) {
        ASSERT_EQ(px[i], 0.5f);
        ASSERT_EQ(px[i + 2], 1.5f);
        ASSERT_EQ(px[i + 3], 1.0f);
    }
}

} // namespace
} // namespace rrc::demo::test
