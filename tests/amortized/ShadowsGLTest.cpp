// rrc-shadows' renderer: exact visibility where PCF's whole disk is lit or shadowed (any k, PCF
// and amortized), the shadow map re-rendered only when the light or the caster moved, per-frame
// rotations that are deterministic yet independent between frames, and the amortized estimate
// converging on the 256-tap reference as the recursive filter predicts.
#include "shadow_test_scene.hpp"

#include "common/fullscreen.hpp"
#include "shadows/shadow_renderer.hpp"
#include "support/gl_test.hpp"

#include <rrc/projection.hpp>

#include <cmath>
#include <optional>

namespace rrc::test {
std::span<const EmbeddedFile> amortizedShaders();
namespace {

using shadows::ShadowFrame;
using shadows::ShadowRenderer;
using shadows::ShadowSettings;
using shadows::Variant;

constexpr int kW = 160, kH = 120;
constexpr float kPenumbra = 0.6f;   // PCF radius, metres: a penumbra wide enough to measure

class ShadowsGLTest : public GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        library.add(amortizedShaders());
        library.add(demo::commonShaders());
        scene.emplace();   // after GLTest::SetUp, which counts the live GL objects
        ASSERT_TRUE(renderer.init(kW, kH, library, scene->draws, scene->boundsMin, scene->boundsMax, 1024));
    }
    ShadowFrame frame(uint32_t number) const {
        return {.view = scene->view, .projection = projection, .toLight = {0.0, 1.0, 0.0}, .caster = scene->parkedCaster,
                .prevCaster = scene->parkedCaster, .frame = number};
    }
    std::vector<float> visibility(Variant v) const {
        std::vector<float> out(kW * kH);
        glGetTextureImage(renderer.visibility(v), 0, GL_RED, GL_FLOAT, int(out.size() * sizeof(float)), out.data());
        return out;
    }
    // The pixel a ground point at (x, 0, z) lands on.
    size_t pixelOf(double x, double z) const {
        const glm::dvec4 c = projection * scene->view * glm::dvec4(x, 0.0, z, 1.0);
        const int px = int((c.x / c.w * 0.5 + 0.5) * kW), py = int((c.y / c.w * 0.5 + 0.5) * kH);
        EXPECT_TRUE(px >= 0 && px < kW && py >= 0 && py < kH) << x << ", " << z;
        return size_t(py) * kW + size_t(px);
    }
    // RMS of a - b over the pixels whose reference lies strictly inside the penumbra.
    static double penumbraRms(const std::vector<float>& a, const std::vector<float>& b, const std::vector<float>& reference) {
        double sum = 0;
        int n = 0;
        for (size_t i = 0; i < a.size(); ++i)
            if (reference[i] > 0.05f && reference[i] < 0.95f) { sum += double(a[i] - b[i]) * (a[i] - b[i]); ++n; }
        EXPECT_GT(n, 150) << "the penumbra must be in view";
        return std::sqrt(sum / std::max(n, 1));
    }

    std::optional<ShadowTestScene> scene;
    glm::dmat4 projection = perspectiveReversedZ(0.9, double(kW) / kH, 0.1);
    ShadowRenderer renderer;
};

TEST_F(ShadowsGLTest, FullyLitIsOneAndFullyShadowedIsZeroForAnyK) {
    const size_t lit[] = {pixelOf(2.0, 0.0), pixelOf(4.0, 1.5), pixelOf(1.0, -1.0)};
    const size_t dark[] = {pixelOf(-1.0, 0.0), pixelOf(-2.5, 1.0), pixelOf(-1.5, -0.5)};
    for (Variant v : {Variant::Pcf, Variant::Amortized})
        for (int k : {1, 3, 4, 16, 256})
            for (uint32_t f = 0; f < 3; ++f) {
                renderer.render(v, {.taps = k, .radius = 0.4f}, frame(f));
                const auto vis = visibility(v);
                for (size_t i : lit) EXPECT_EQ(vis[i], 1.0f) << shadows::variantName(v) << " k=" << k;
                for (size_t i : dark) EXPECT_EQ(vis[i], 0.0f) << shadows::variantName(v) << " k=" << k;
            }
}

TEST_F(ShadowsGLTest, ShadowMapRenderedOnlyWhenTheLightOrTheCasterMoved) {
    ShadowFrame f = frame(0);
    renderer.render(Variant::Pcf, {}, f);
    EXPECT_EQ(renderer.shadowMapRenders(), 1);
    EXPECT_EQ(renderer.staticShadowRenders(), 1);
    f.view = glm::translate(f.view, glm::dvec3(0.3, 0.0, 0.1));   // the camera alone moved
    for (uint32_t i = 1; i < 4; ++i) {
        f.frame = i;
        renderer.render(i % 2 ? Variant::Amortized : Variant::Pcf, {}, f);
    }
    EXPECT_EQ(renderer.shadowMapRenders(), 1);
    f.caster = glm::translate(f.caster, glm::dvec3(0.0, 0.0, 0.5));
    renderer.render(Variant::Amortized, {}, f);
    renderer.render(Variant::Amortized, {}, f);
    EXPECT_EQ(renderer.shadowMapRenders(), 2);
    EXPECT_EQ(renderer.staticShadowRenders(), 1) << "the caster alone moved: the static depth is reused";
    f.toLight = glm::normalize(glm::dvec3(0.2, 1.0, 0.0));
    renderer.render(Variant::Pcf, {}, f);
    EXPECT_EQ(renderer.shadowMapRenders(), 3);
    EXPECT_EQ(renderer.staticShadowRenders(), 2);
}

TEST_F(ShadowsGLTest, CasterOverTheStaticDepthCastsItsShadow) {
    // The caster parked over lit ground must darken it: the map is the static depth plus the caster.
    const size_t under = pixelOf(3.0, 0.0);
    renderer.render(Variant::Pcf, {.taps = 16}, frame(0));
    EXPECT_EQ(visibility(Variant::Pcf)[under], 1.0f);
    ShadowFrame f = frame(1);
    f.caster = f.prevCaster = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, 0.3, 0.0)), glm::dvec3(1.0, 0.2, 1.0));
    renderer.render(Variant::Pcf, {.taps = 16}, f);
    EXPECT_EQ(visibility(Variant::Pcf)[under], 0.0f);
    EXPECT_EQ(renderer.staticShadowRenders(), 1);
}

TEST_F(ShadowsGLTest, RotationsAreDeterministicAndIndependentBetweenFrames) {
    renderer.render(Variant::Pcf, {.taps = 256, .radius = kPenumbra}, frame(0));
    const auto reference = visibility(Variant::Pcf);
    renderer.render(Variant::Pcf, {.taps = 4, .radius = kPenumbra}, frame(5));
    const auto a = visibility(Variant::Pcf);
    renderer.render(Variant::Pcf, {.taps = 4, .radius = kPenumbra}, frame(5));
    EXPECT_EQ(a, visibility(Variant::Pcf)) << "same frame and seed: same rotation";
    renderer.render(Variant::Pcf, {.taps = 4, .radius = kPenumbra}, frame(6));
    const auto b = visibility(Variant::Pcf);
    // Independent frames with error e each: |a - b| has RMS sqrt(2) e; fully correlated ones 0.
    const double ea = penumbraRms(a, reference, reference), eb = penumbraRms(b, reference, reference);
    const double between = penumbraRms(a, b, reference);
    EXPECT_NEAR(between / std::sqrt(0.5 * (ea * ea + eb * eb)), std::sqrt(2.0), 0.25);
}

TEST_F(ShadowsGLTest, AmortizedConvergesToTheReferenceAsTheFilterPredicts) {
    renderer.render(Variant::Pcf, {.taps = 256, .radius = kPenumbra}, frame(0));
    const auto reference = visibility(Variant::Pcf);
    double pcf2 = 0;
    for (uint32_t f = 1; f <= 8; ++f) {
        renderer.render(Variant::Pcf, {.taps = 4, .radius = kPenumbra}, frame(f));
        const double e = penumbraRms(visibility(Variant::Pcf), reference, reference);
        pcf2 += e * e / 8;
    }
    // Static camera, lambda 0.6: the filter keeps the mean and scales the variance by
    // (1 - lambda) / (1 + lambda) = 1/4, so the error halves (the reference's own noise and the
    // bilinear resampling of the cache aside).
    double amortized2 = 0;
    for (uint32_t f = 1; f <= 40; ++f) {
        renderer.render(Variant::Amortized, {.taps = 4, .lambda = 0.6f, .radius = kPenumbra}, frame(100 + f));
        if (f <= 20) continue;
        const double e = penumbraRms(visibility(Variant::Amortized), reference, reference);
        amortized2 += e * e / 20;
    }
    const double ratio = std::sqrt(amortized2 / pcf2);
    std::printf("PCF 4 RMS %.4f, amortized RMS %.4f, ratio %.3f (predicted 0.5)\n", std::sqrt(pcf2), std::sqrt(amortized2), ratio);
    EXPECT_NEAR(ratio, 0.5, 0.12);
}

} // namespace
} // namespace rrc::test
