// rrc-bump-env's renderer: with a flat bump map the sphere shows exactly the analytic
// reflection (ray-sphere intersection, reflect, bilinear cube-map lookup done on the CPU from the
// PNG faces); the sub-pixel jitter is deterministic per frame and seed yet changes between
// frames; the amortized estimate converges on the 256-sample reference as the filter predicts.
#include "bump_env/bump_env_renderer.hpp"
#include "common/fullscreen.hpp"
#include "support/gl_test.hpp"

#include <rrc/image.hpp>
#include <rrc/projection.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>

namespace rrc::test {
std::span<const EmbeddedFile> amortizedShaders();
namespace {

using bump_env::BumpEnvRenderer;
using bump_env::BumpFrame;
using bump_env::Variant;

constexpr int kW = 161, kH = 121;   // odd: the centre pixel looks exactly at the sphere's centre
const std::string kAssets = std::string(RRC_SOURCE_DIR) + "/assets";

// Bilinear lookup in the PNG faces, following the face layout of assets/env/README.md.
struct CpuCubeMap {
    std::array<OIIO::ImageBuf, 6> faces;   // px nx py ny pz nz
    int size = 0;
    CpuCubeMap() {
        const char* names[] = {"px", "nx", "py", "ny", "pz", "nz"};
        for (int i = 0; i < 6; ++i) faces[i] = readImage(kAssets + "/env/" + names[i] + ".png").value();
        size = faces[0].spec().width;
    }
    glm::dvec3 texel(int face, int x, int y) const {
        float p[4] = {};
        faces[face].getpixel(std::clamp(x, 0, size - 1), std::clamp(y, 0, size - 1), p, 3);
        return {p[0], p[1], p[2]};
    }
    glm::dvec3 sample(glm::dvec3 d) const {
        const glm::dvec3 a = glm::abs(d);
        int face;
        double sc, tc, ma;
        if (a.x >= a.y && a.x >= a.z) { face = d.x > 0 ? 0 : 1; ma = a.x; sc = d.x > 0 ? -d.z : d.z; tc = -d.y; }
        else if (a.y >= a.z) { face = d.y > 0 ? 2 : 3; ma = a.y; sc = d.x; tc = d.y > 0 ? d.z : -d.z; }
        else { face = d.z > 0 ? 4 : 5; ma = a.z; sc = d.z > 0 ? d.x : -d.x; tc = -d.y; }
        const double x = (sc / ma + 1) * 0.5 * size - 0.5, y = (tc / ma + 1) * 0.5 * size - 0.5;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        return glm::mix(glm::mix(texel(face, x0, y0), texel(face, x0 + 1, y0), fx),
                        glm::mix(texel(face, x0, y0 + 1), texel(face, x0 + 1, y0 + 1), fx), fy);
    }
};

class BumpEnvGLTest : public GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        library.add(amortizedShaders());
        library.add(demo::commonShaders());
        ASSERT_TRUE(renderer.init(kW, kH, library, kAssets));
    }
    BumpFrame frame(uint32_t number) const { return {.view = view, .projection = projection, .frame = number}; }
    std::vector<uint8_t> pixels() const {
        std::vector<uint8_t> p(size_t(kW) * kH * 4);
        glGetTextureImage(renderer.color(), 0, GL_RGBA, GL_UNSIGNED_BYTE, int(p.size()), p.data());
        return p;
    }
    // RMS over the sphere's pixels (those where the reference differs from the background).
    static double sphereRms(const std::vector<uint8_t>& a, const std::vector<uint8_t>& reference, const std::vector<bool>& mask) {
        double sum = 0;
        long n = 0;
        for (size_t i = 0; i < mask.size(); ++i)
            if (mask[i]) {
                for (int c = 0; c < 3; ++c) sum += std::pow((double(a[i * 4 + c]) - reference[i * 4 + c]) / 255.0, 2);
                n += 3;
            }
        return std::sqrt(sum / std::max(n, 1L));
    }

    glm::dvec3 eye{2.2, 0.3, 0.9};
    glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
    glm::dmat4 projection = perspectiveReversedZ(0.9, double(kW) / kH, 0.1);
    BumpEnvRenderer renderer;
};

TEST_F(BumpEnvGLTest, FlatBumpShowsTheAnalyticReflection) {
    renderer.render(Variant::Brute, {.grid = 1, .jitter = false, .bumpStrength = 0.0f}, frame(0));
    const auto image = pixels();
    const CpuCubeMap cube;
    const glm::dmat4 inverse = glm::inverse(projection * view);
    double worst = 0, sum = 0;
    int n = 0;
    for (int py = 4; py < kH; py += 6)
        for (int px = 4; px < kW; px += 6) {
            const glm::dvec2 ndc((px + 0.5) / kW * 2 - 1, (py + 0.5) / kH * 2 - 1);
            const glm::dvec4 a = inverse * glm::dvec4(ndc, 1.0, 1.0), b = inverse * glm::dvec4(ndc, 0.5, 1.0);
            const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::normalize(glm::dvec3(b) / b.w - o);
            const double half = glm::dot(o, d), c = glm::dot(o, o) - 1.0, disc = half * half - c;
            if (disc <= 0) continue;
            const glm::dvec3 normal = o + d * (-half - std::sqrt(disc));   // unit sphere: the hit is the normal
            if (glm::dot(normal, -d) < 0.5) continue;                       // grazing: tessellation dominates
            const glm::dvec3 expected = cube.sample(glm::reflect(d, normal));
            for (int ch = 0; ch < 3; ++ch) {
                const double e = std::abs(image[(size_t(py) * kW + px) * 4 + ch] / 255.0 - expected[ch]);
                worst = std::max(worst, e);
                sum += e;
                ++n;
            }
        }
    ASSERT_GT(n, 300);
    std::printf("flat bump: %d channel samples, mean |error| %.4f, max %.4f\n", n, sum / n, worst);
    EXPECT_LT(sum / n, 1.5 / 255.0);
    EXPECT_LT(worst, 24.0 / 255.0);
    // The centre pixel reflects straight back: the environment towards the eye.
    const auto centre = cube.sample(glm::normalize(eye));
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(image[(size_t(kH / 2) * kW + kW / 2) * 4 + ch] / 255.0, centre[ch], 3.0 / 255.0);
}

TEST_F(BumpEnvGLTest, JitterIsDeterministicPerFrameAndChangesBetweenFrames) {
    renderer.render(Variant::Brute, {.grid = 2}, frame(3));
    const auto a = pixels();
    renderer.render(Variant::Brute, {.grid = 2}, frame(3));
    EXPECT_EQ(a, pixels());
    renderer.render(Variant::Brute, {.grid = 2}, frame(4));
    EXPECT_NE(a, pixels());
    renderer.render(Variant::Brute, {.grid = 2, .seed = 2}, frame(3));
    EXPECT_NE(a, pixels());
}

TEST_F(BumpEnvGLTest, AmortizedConvergesToTheReferenceAsTheFilterPredicts) {
    renderer.render(Variant::Brute, {.grid = 16, .jitter = false}, frame(0));
    const auto reference = pixels();
    renderer.render(Variant::Brute, {.grid = 16, .jitter = false, .bumpStrength = 0.0f}, frame(0));
    const auto flat = pixels();
    std::vector<bool> sphere(size_t(kW) * kH);
    for (size_t i = 0; i < sphere.size(); ++i)   // the bump changes the sphere, not the background
        for (int c = 0; c < 3; ++c) sphere[i] = sphere[i] || reference[i * 4 + c] != flat[i * 4 + c];
    double brute2 = 0, amortized2 = 0;
    for (uint32_t f = 1; f <= 8; ++f) {
        renderer.render(Variant::Brute, {.grid = 2}, frame(f));
        brute2 += std::pow(sphereRms(pixels(), reference, sphere), 2) / 8;
    }
    for (uint32_t f = 1; f <= 40; ++f) {
        renderer.render(Variant::Amortized, {.grid = 2, .lambda = 0.6f}, frame(100 + f));
        if (f > 20) amortized2 += std::pow(sphereRms(pixels(), reference, sphere), 2) / 20;
    }
    // Static camera, lambda 0.6: variance x (1 - lambda) / (1 + lambda) = 1/4, error halved.
    const double ratio = std::sqrt(amortized2 / brute2);
    std::printf("4 samples RMS %.4f, amortized RMS %.4f, ratio %.3f (predicted 0.5)\n", std::sqrt(brute2), std::sqrt(amortized2), ratio);
    EXPECT_NEAR(ratio, 0.5, 0.12);
}

} // namespace
} // namespace rrc::test
