// Depth precision of the hit test: false hits and false misses over distances, near and far
// planes, for standard depth and reversed-Z 32F (issue item f), and a scene translated 1e5 units
// from the origin (g).
#include "stress_scene.hpp"
#include "support/gl_test.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>

namespace rrc::test {
namespace {

class StressDepth : public GLTest {};

const char* kLocalBody = R"(
vec4 onMiss() { return vec4(v_local, 0.25, 1.0); }
vec4 onHit(rrc_Lookup l, vec4 cached) { return cached; }
)";

std::string farName(double far) {
    if (std::isinf(far)) return "inf";
    char buf[16];
    std::snprintf(buf, sizeof(buf), "%.0e", far);
    return buf;
}

// Issue item f. Two fronto-parallel planes filling the view, A at distance z and B at z (1 + r).
// False hits: render one, then the other from the same camera; every hit took its value from
// the other surface. False misses: render A, then A again from the same camera and from a camera
// moved 0.37 pixels sideways; every disoccluded pixel missed its own surface.
TEST_F(StressDepth, DepthToleranceSweepCountsFalseHitsAndFalseMisses) {
    constexpr int W = 64, H = 48;
    const double ratios[] = {0.005, 0.02, 0.1};   // the default tolerance is 0.01 (relative)
    const double nears[] = {1e-3, 0.1};
    const double fars[] = {1e3, 1e5, 1e7, kInfiniteFar};
    const double distances[] = {0.1, 1.0, 10.0, 100.0, 1e3, 1e4};
    std::printf("depth sweep %dx%d, tolerance 0.01 relative: false hits (of %d pixels, both orders summed) per "
                "separation dz/z, false misses static / moved 0.37 px\n", W, H, 2 * W * H);
    std::printf("%-8s %-6s %-5s %-7s %10s %10s %10s %8s %8s\n", "depth", "near", "far", "z", "FH 0.005", "FH 0.02",
                "FH 0.1", "FM stat", "FM move");
    size_t standardFalse = 0, reversedFalse = 0, rows = 0;
    for (bool reversed : {false, true}) {
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = GL_RGBA8}}, .reversedZ = reversed}).value();
        StressScene scene(cache, kLocalBody);
        auto counts = [&](const Camera& camera, const glm::dmat4& model) {
            const Object objects[] = {{.model = model, .prevModel = model}};
            EXPECT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
            return cache.finishStats();
        };
        for (double near : nears)
            for (double far : fars)
                for (double z : distances) {
                    if (z <= 2.0 * near || z * 1.1 >= 0.9 * far) continue;
                    Camera camera{.near = near, .far = far};
                    auto plane = [&](double d) { return quadAt({0, 0, -d}, {2.0 * d, 2.0 * d}); };
                    size_t falseHits[3] = {};
                    for (int k = 0; k < 3; ++k) {
                        const glm::dmat4 a = plane(z), b = plane(z * (1.0 + ratios[k]));
                        for (int order = 0; order < 2; ++order) {
                            cache.invalidate();
                            counts(camera, order ? b : a);
                            falseHits[k] += counts(camera, order ? a : b).hits;
                        }
                    }
                    cache.invalidate();
                    counts(camera, plane(z));
                    const size_t staticMisses = counts(camera, plane(z)).counts[int(Outcome::Disoccluded)];
                    Camera moved = camera;
                    const double shift = 0.37 * 2.0 * z * std::tan(camera.fovy / 2.0) / H;
                    moved.eye.x += shift;
                    moved.target.x += shift;
                    const size_t movedMisses = counts(moved, plane(z)).counts[int(Outcome::Disoccluded)];
                    char zName[16];
                    std::snprintf(zName, sizeof(zName), "%g", z);
                    std::printf("%-8s %-6g %-5s %-7s %10zu %10zu %10zu %8zu %8zu\n", reversed ? "reversed" : "standard", near,
                                farName(far).c_str(), zName, falseHits[0], falseHits[1], falseHits[2], staticMisses, movedMisses);
                    ++rows;
                    const size_t wrong = falseHits[1] + falseHits[2] + staticMisses + movedMisses;
                    (reversed ? reversedFalse : standardFalse) += wrong;
                    if (reversed) {
                        // Separable surfaces (dz/z above the tolerance) never hit each other, and a
                        // surface always finds itself.
                        EXPECT_EQ(falseHits[1] + falseHits[2], 0u) << "near " << near << " far " << far << " z " << z;
                        EXPECT_EQ(staticMisses + movedMisses, 0u) << "near " << near << " far " << far << " z " << z;
                    }
                }
    }
    std::printf("depth sweep: %zu configurations; wrong outcomes where dz/z > tolerance: standard %zu, reversed-Z %zu\n",
                rows, standardFalse, reversedFalse);
}

// Issue item g: the same animated scene with everything (objects and camera) translated by 1e5
// units gives the same outcomes and the same payload (quad coordinates, so the comparison does not
// depend on how precisely world positions themselves can be stored).
TEST_F(StressDepth, SceneTranslatedByOneHundredThousandMatchesTheUntranslatedRun) {
    constexpr int W = 96, H = 64, kFrames = 8;
    struct Run { std::vector<std::vector<uint32_t>> outcomes; std::vector<std::vector<glm::vec4>> payloads; std::vector<uint64_t> hits; };
    auto run = [&](glm::dvec3 offset) {
        Run r;
        Cache cache = Cache::create({.width = W, .height = H, .payloads = {{.format = GL_RGBA32F}}, .objectIds = true}).value();
        StressScene scene(cache, kLocalBody);
        const glm::dmat4 shift = glm::translate(glm::dmat4(1.0), offset);
        auto boxAt = [&](int f) { return shift * quadAt({-1.0 + 0.21 * f, 0.3 - 0.07 * f, -5.0}, {0.8, 0.6}); };
        for (int f = 0; f < kFrames; ++f) {
            const glm::dmat4 wall = shift * quadAt({0, 0, -12}, {40, 40});
            const glm::dmat4 still = shift * glm::rotate(quadAt({1.5, -0.5, -7}, {1.2, 1.0}), 0.6, glm::dvec3(0, 1, 0));
            const Object objects[] = {{.model = wall, .prevModel = wall, .id = 1},
                                      {.model = still, .prevModel = still, .id = 2},
                                      {.model = boxAt(f), .prevModel = boxAt(f - 1), .id = 3}};
            Camera camera{.eye = offset + glm::dvec3(0.05 * f, 0.02 * f, -0.03 * f),
                          .target = offset + glm::dvec3(0.04 * f, 0.0, -1.0)};
            EXPECT_TRUE(scene.frame(cache, ControlFlow::TwoPass, camera, objects));
            r.outcomes.push_back(readUint(cache.outcomes()));
            r.payloads.push_back(readRGBA(cache.payload(0)));
            r.hits.push_back(cache.finishStats().hits);
        }
        return r;
    };
    const Run a = run(glm::dvec3(0.0)), b = run(glm::dvec3(1e5, -1e5, 1e5));
    size_t worstMismatch = 0;
    double worstPayload = 0;
    for (int f = 0; f < kFrames; ++f) {
        size_t mismatched = 0;
        double payload = 0;
        for (size_t i = 0; i < a.outcomes[f].size(); ++i) {
            mismatched += a.outcomes[f][i] != b.outcomes[f][i];
            payload = std::max(payload, double(glm::length(a.payloads[f][i] - b.payloads[f][i])));
        }
        std::printf("translated 1e5, frame %d: hits %llu vs %llu, %zu of %d outcomes differ, max payload difference %.3g\n", f,
                    static_cast<unsigned long long>(a.hits[f]), static_cast<unsigned long long>(b.hits[f]), mismatched, W * H,
                    payload);
        worstMismatch = std::max(worstMismatch, mismatched);
        worstPayload = std::max(worstPayload, payload);
        EXPECT_LE(mismatched, size_t(W * H / 500)) << "frame " << f;   // a few edge pixels at most
        EXPECT_NEAR(double(a.hits[f]), double(b.hits[f]), W * H / 500.0) << "frame " << f;
    }
    EXPECT_GT(a.hits.back(), size_t(W * H / 2));
    std::printf("translated 1e5: worst %zu outcome mismatches, worst payload difference %.3g\n", worstMismatch, worstPayload);
}

} // namespace
} // namespace rrc::test
