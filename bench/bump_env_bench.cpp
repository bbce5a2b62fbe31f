// rrc-bump-env's rows (chapter section 6.5.4): k = 1, 4, 9, 16 samples per pixel against 4
// samples amortized through the cache (lambda 0.6), taking turns on every frame of a camera orbit,
// compared with 256 samples (16 x 16 stratum centres) rendered for the same frame; the lambda
// sweep runs alongside. Then the convergence after a camera move (bump_env_convergence.json).
#include "amortized_support.hpp"
#include "bench_scenes.hpp"

#include "bump_env/bump_env_renderer.hpp"
#include "bump_env/bump_env_scene.hpp"
#include "common/fullscreen.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <memory>

namespace rrc::bench {
namespace {

using namespace bump_env;
using namespace amortized;

std::vector<Record> runBumpEnv(const Options& options, ShaderLibrary& library);
const DemoRegistration registration{"bump_env", 4, runBumpEnv};

struct Run {
    const char* variant;
    int grid;
    float lambda;   // < 0: brute force
    int renderer;   // each amortized lambda needs its own cache
    Tally tally;
    Variant kind() const { return lambda < 0 ? Variant::Brute : Variant::Amortized; }
};

glm::dmat4 viewAt(double t) {
    const demo::Pose p = cameraOrbit().at(t);
    return glm::lookAt(p.position, p.target, p.up);
}

// Camera still at A, a jump to B (3 s further round the orbit), still again: per-frame RMSE of
// each lambda against the reference at B; brute-force k as flat lines.
void runConvergence(const Options& options, std::vector<std::unique_ptr<BumpEnvRenderer>>& renderers, const float* sweep,
                    const glm::dmat4& projection, Record& amortizedRecord) {
    const int w = options.width, h = options.height;
    uint32_t frameNumber = 100000;
    auto frame = [&](double t) { return BumpFrame{.view = viewAt(t), .projection = projection, .frame = frameNumber++}; };
    const int after = options.smoke ? 5 : 12;
    for (auto& r : renderers) r->cache().invalidate();   // a clean start at A
    for (int f = 0; f < (options.smoke ? 3 : 6); ++f)
        for (size_t i = 0; i < renderers.size(); ++i) renderers[i]->render(Variant::Amortized, {.lambda = sweep[i]}, frame(6.0));
    renderers[0]->render(Variant::Brute, {.grid = 16, .jitter = false}, frame(9.0));
    const Pixels reference = readRgba8(renderers[0]->color(), w, h);
    std::map<std::string, std::vector<double>> series;
    for (int grid : {1, 2, 3, 4}) {
        double e2 = 0;
        for (int f = 0; f < 4; ++f) {
            renderers[0]->render(Variant::Brute, {.grid = grid}, frame(9.0));
            const double e = rmse(readRgba8(renderers[0]->color(), w, h), reference);
            e2 += e * e / 4;
        }
        series["brute" + std::to_string(grid * grid)] = std::vector<double>(after, std::sqrt(e2));
    }
    for (int f = 0; f < after; ++f)
        for (size_t i = 0; i < renderers.size(); ++i) {
            renderers[i]->render(Variant::Amortized, {.lambda = sweep[i]}, frame(9.0));
            char name[32];
            std::snprintf(name, sizeof name, "amortized_l%.2f", sweep[i]);
            series[name].push_back(rmse(readRgba8(renderers[i]->color(), w, h), reference));
        }
    writeSeries(options, "bump_env_convergence.json", series);
    amortizedRecord.extra["rmse_converged_static"] = series["amortized_l0.60"].back();
    amortizedRecord.extra["rmse_brute9_static"] = series["brute9"].front();
    amortizedRecord.extra["rmse_brute16_static"] = series["brute16"].front();
}

std::vector<Record> runBumpEnv(const Options& options, ShaderLibrary& library) {
    library.add(demo::commonShaders());
    const int w = options.width, h = options.height;
    const float sweep[] = {0.6f, 0.4f, 0.75f, 0.9f};
    std::vector<std::unique_ptr<BumpEnvRenderer>> renderers;
    for (int i = 0; i < 4; ++i) {
        renderers.push_back(std::make_unique<BumpEnvRenderer>());
        if (auto r = renderers.back()->init(w, h, library); !r) return {};
    }
    std::vector<Run> runs = {{"brute", 1, -1, 0, {}}, {"brute", 2, -1, 0, {}}, {"brute", 3, -1, 0, {}}, {"brute", 4, -1, 0, {}},
                             {"amortized", 2, 0.6f, 0, {}}, {"amortized (lambda sweep)", 2, 0.4f, 1, {}},
                             {"amortized (lambda sweep)", 2, 0.75f, 2, {}}, {"amortized (lambda sweep)", 2, 0.9f, 3, {}}};
    const glm::dmat4 projection = demo::perspective(0.9, double(w) / h, 0.1);
    auto frameAt = [&](int f) {
        return BumpFrame{.view = viewAt(f / 60.0), .projection = projection, .frame = uint32_t(f)};
    };
    auto render = [&](const Run& run, const BumpFrame& frame) {
        renderers[run.renderer]->render(run.kind(), {.grid = run.grid, .lambda = std::max(run.lambda, 0.0f)}, frame);
    };
    const Run reference{"reference", 16, -1, 0, {}};
    auto renderReference = [&](const BumpFrame& frame) { renderers[0]->render(Variant::Brute, {.grid = 16, .jitter = false}, frame); };
    // Half the common frame count: 6-8 variants per frame and the sweeps must fit the demos'
    // share of scripts/demo's time; the reference (256 samples) on every 5th frame.
    const int frames = std::max(2, options.frames / 2);
    const int checkEvery = std::max(1, std::min(5, frames / 3));
    Tally referenceTally;
    double hits = 0, lookups = 0;
    std::fprintf(stderr, "bump_env: %d frames x %zu variants, interleaved; reference every %d frames (load %s)\n", frames,
                 runs.size(), checkEvery, loadAverage().c_str());
    Pixels referencePixels;
    for (int f = -options.warmup; f < frames; ++f) {
        const BumpFrame frame = frameAt(f + options.warmup);
        const bool check = f >= 0 && f % checkEvery == 0;
        if (check) {
            referenceTally.ms.push_back(timeOnce([&] { renderReference(frame); }));
            referencePixels = readRgba8(renderers[0]->color(), w, h);
        }
        for (Run& run : runs) {
            const double ms = timeOnce([&] { render(run, frame); });
            if (f < 0) continue;
            run.tally.ms.push_back(ms);
            if (check) run.tally.addError(rmse(readRgba8(renderers[run.renderer]->color(), w, h), referencePixels));
            if (check && run.lambda == 0.6f) {
                const Stats s = renderers[0]->cache().finishStats();
                hits += double(s.hits);
                lookups += double(s.hits + s.misses + s.forced + s.refreshed);
            }
        }
    }
    std::vector<Record> records;
    // One frame past the sequence: the amortized caches continue into it, brute force renders it too.
    const BumpFrame lastFrame = frameAt(frames + options.warmup);
    renderReference(lastFrame);
    const Pixels refLast = readRgba8(renderers[0]->color(), w, h);
    Record ref{.demo = "bump_env", .variant = "reference", .samples = 256, .width = w, .height = h, .frames = int(referenceTally.ms.size())};
    ref.timing = referenceTally.timing();
    ref.rmse = 0.0;
    ref.psnr = INFINITY;
    ref.images["256 samples"] = savePng(options, renderers[0]->color(), "bump_env_reference.png");
    for (Run& run : runs) {
        Record r{.demo = "bump_env", .variant = run.variant, .samples = run.grid * run.grid, .width = w, .height = h, .frames = frames};
        if (run.lambda >= 0) r.lambda = run.lambda;
        r.timing = run.tally.timing();
        r.rmse = run.tally.rmse();
        r.psnr = psnr(*r.rmse);
        if (run.lambda < 0 || run.lambda == 0.6f) {
            render(run, lastFrame);
            const std::string stem = "bump_env_" + std::string(run.lambda < 0 ? "brute" : "amortized") + std::to_string(run.grid * run.grid);
            r.images["frame"] = savePng(options, renderers[run.renderer]->color(), stem + ".png");
            saveRgba8Difference(options, readRgba8(renderers[0]->color(), w, h), refLast, w, h, 4.0f, stem + "_diff.png", r, "difference x4");
        }
        if (run.lambda == 0.6f) {
            r.hitRate = lookups > 0 ? hits / lookups : 0.0;
            Texture vis;
            renderers[0]->cache().visualize(vis);
            r.images["hits (green) / misses (red)"] = savePng(options, vis.id(), "bump_env_amortized_hits.png");
        }
        std::fprintf(stderr, "bump_env %-26s k=%3d lambda %.2f  median %7.2f ms  min %7.2f ms  RMSE %.5f\n", run.variant,
                     run.grid * run.grid, std::max(run.lambda, 0.0f), r.timing.median, r.timing.min, *r.rmse);
        records.push_back(std::move(r));
    }
    records.push_back(std::move(ref));
    Record& amortized = *std::find_if(records.begin(), records.end(), [](const Record& r) { return r.variant == "amortized"; });
    runConvergence(options, renderers, sweep, projection, amortized);
    return records;
}

} // namespace
} // namespace rrc::bench
