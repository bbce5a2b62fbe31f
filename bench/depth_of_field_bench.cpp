// rrc-bench's depth_of_field rows: brute force against the cached variant (each lens view reuses
// the previous view's cache) for N Poisson-disk lens samples, visited in nearest-neighbour order
// and, as a comparison, in random order; errors against brute force with 64 samples.
#include "accumulation_sweep.hpp"

#include "depth_of_field/lens.hpp"

#include "common/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <rrc/projection.hpp>

namespace rrc::bench {
namespace {

std::vector<Record> runDepthOfField(const Options& options, ShaderLibrary& library);
const DemoRegistration registration{"depth_of_field", 2, runDepthOfField};

std::vector<Record> runDepthOfField(const Options& options, ShaderLibrary& library) {
    // The procedural colonnade, whatever --scene says: a few hundred triangles, so shading dominates
    // as in the chapter's 2.5k-triangle test. On the temple (124,800 triangles) each geometry pass
    // costs tens of ms on llvmpipe and the cache cannot pay (docs/stereo.md, docs/motion_blur.md).
    const auto scene = loadBenchScene("procedural");
    if (!scene) return {};
    accumulation::AccumulationRenderer renderer;
    if (auto r = renderer.init(options.width, options.height, library,
                               {.flow = options.cachedFlow(), .probe = options.probe()});
        !r)
        return {};
    const double aperture = 0.12, focus = 9.0;   // as rrc-depth-of-field's defaults
    const demo::FlyPath path = demo::FlyPath::colonnade({scene->boundsMin, scene->boundsMax});
    const glm::dmat4 projection = perspectiveReversedZ(0.9, double(options.width) / options.height, 0.1);
    auto render = [&](accumulation::Variant variant, dof::LensOrder order) {
        return [&, variant, order](int n, double time, bool trackHits) {
            const demo::Pose pose = path.at(time);
            const glm::dmat4 view = glm::lookAt(pose.position, pose.target, pose.up);
            const auto lens = dof::ordered(dof::poissonDisk(n), order);
            const accumulation::SceneRef ref{.statics = scene->draws, .moving = false};
            renderer.render(variant, ref, n, [&](int i, int) {
                return accumulation::SampleView{dof::lensView(view, lens[size_t(i)] * aperture, focus), projection};
            }, trackHits);
        };
    };
    using accumulation::Variant;
    using dof::LensOrder;
    accumulation_sweep::Sweep sweep{.demo = "depth_of_field"};
    const std::vector<int> bruteN = options.smoke ? std::vector<int>{2, 8, 16} : std::vector<int>{2, 4, 8, 16, 32};
    const std::vector<int> cachedN = options.smoke ? std::vector<int>{2, 8, 16, 20, 24}
                                                   : std::vector<int>{2, 4, 8, 12, 16, 20, 24, 32};
    const std::vector<int> randomN = options.smoke ? std::vector<int>{16} : std::vector<int>{8, 16, 32};
    sweep.arms.push_back({"brute", Variant::Brute, bruteN, render(Variant::Brute, LensOrder::NearestNeighbour)});
    sweep.arms.push_back({"cached", Variant::Cached, cachedN, render(Variant::Cached, LensOrder::NearestNeighbour)});
    sweep.arms.push_back({"cached-random-order", Variant::Cached, randomN, render(Variant::Cached, LensOrder::Random)});
    sweep.frameTimes = options.smoke ? std::vector<double>{2.0} : std::vector<double>{1.0, 2.5};
    std::fprintf(stderr, "depth_of_field: %zu frames, aperture %.2f m, focus %.1f m, reference %d samples\n",
                 sweep.frameTimes.size(), aperture, focus, sweep.referenceSamples);
    auto records = accumulation_sweep::run(options, renderer, sweep);
    for (Record& r : records) {
        if (r.variant == "reference") continue;
        const auto lens = dof::poissonDisk(r.samples);
        const LensOrder order = r.variant == "cached-random-order" ? LensOrder::Random : LensOrder::NearestNeighbour;
        r.extra["lens_path_length"] = dof::pathLength(dof::ordered(lens, order));   // in lens radii
    }
    return records;
}

} // namespace
} // namespace rrc::bench
