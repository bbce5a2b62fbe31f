// rrc-bench's motion_blur rows: brute force against the cached variant (each time sample reuses
// the previous one's cache) for N time samples per frame, errors against brute force with 64.
#include "accumulation_sweep.hpp"

#include "motion_blur/shutter.hpp"

#include <rrc/projection.hpp>

namespace rrc::bench {
namespace {

std::vector<Record> runMotionBlur(const Options& options, ShaderLibrary& library);
const DemoRegistration registration{"motion_blur", 1, runMotionBlur};

std::vector<Record> runMotionBlur(const Options& options, ShaderLibrary& library) {
    // The procedural colonnade, whatever --scene says: a few hundred triangles, so shading dominates
    // as in the chapter's 2.5k-triangle test. On the temple (124,800 triangles) each geometry pass
    // costs tens of ms on llvmpipe and the cache cannot pay (docs/stereo.md, docs/motion_blur.md).
    const auto scene = loadBenchScene("procedural");
    if (!scene) return {};
    auto character = accumulation::Character::load("assets/character.glb");
    if (!character) return {};
    accumulation::AccumulationRenderer renderer;
    if (auto r = renderer.init(options.width, options.height, library,
                               {.flow = options.cachedFlow(), .probe = options.probe()});
        !r)
        return {};
    const motion_blur::Shot shot;
    const glm::dmat4 projection = perspectiveReversedZ(0.9, double(options.width) / options.height, 0.1);
    auto render = [&](accumulation::Variant variant) {
        return [&, variant](int n, double time, bool trackHits) {
            const accumulation::SceneRef ref{.statics = scene->draws, .character = &character.value()};
            renderer.render(variant, ref, n, [&](int i, int count) {
                const double t = motion_blur::sampleTime(shot, time, i, count);
                character.value().pose(t, motion_blur::characterPlacement(shot, t));
                return accumulation::SampleView{motion_blur::cameraView(shot, t), projection};
            }, trackHits);
        };
    };
    accumulation_sweep::Sweep sweep{.demo = "motion_blur"};
    const std::vector<int> bruteN = options.smoke ? std::vector<int>{2, 8, 16} : std::vector<int>{2, 4, 8, 16, 32};
    const std::vector<int> cachedN = options.smoke ? std::vector<int>{2, 8, 16, 20, 24}
                                                   : std::vector<int>{2, 4, 8, 12, 16, 20, 24, 32};
    sweep.arms.push_back({"brute", accumulation::Variant::Brute, bruteN, render(accumulation::Variant::Brute)});
    sweep.arms.push_back({"cached", accumulation::Variant::Cached, cachedN, render(accumulation::Variant::Cached)});
    sweep.frameTimes = options.smoke ? std::vector<double>{0.3} : std::vector<double>{0.1, 0.4};
    std::fprintf(stderr, "motion_blur: %zu frames, shutter %.1f ms, brute N up to %d, cached up to %d, reference %d\n",
                 sweep.frameTimes.size(), shot.shutter * 1000, bruteN.back(), cachedN.back(), sweep.referenceSamples);
    return accumulation_sweep::run(options, renderer, sweep);
}

} // namespace
} // namespace rrc::bench
