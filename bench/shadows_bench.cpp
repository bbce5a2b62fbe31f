// rrc-bench's shadows rows (chapter section 6.5.5): k-tap rotated PCF (k = 4, 16) against 4 taps
// amortized through the cache (lambda 0.75, the sweep's lowest error), all taking turns on every
// frame of one moving sequence (fly-through, walking caster) and compared with 256-tap PCF
// rendered for the same frame; the lambda sweep runs alongside. Then the convergence after a
// camera move: the camera jumps and holds still, and the amortized error is tracked frame by frame.
#include "amortized_support.hpp"
#include "bench_scenes.hpp"

#include "common/fullscreen.hpp"
#include "shadows/shadow_renderer.hpp"
#include "shadows/shadow_scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <functional>
#include <memory>

namespace rrc::bench {
namespace {

using namespace shadows;
using namespace amortized;

std::vector<Record> runShadows(const Options& options, ShaderLibrary& library);
const DemoRegistration registration{"shadows", 3, runShadows};

struct Run {
    const char* variant;
    int taps;
    float lambda;       // < 0: not amortized
    int renderer;       // which ShadowRenderer (each amortized lambda needs its own cache)
    Tally tally;
    bool blur = false;  // fig. 6.9e's depth-aware blur, fed back into the cache
};

// The camera holds still at A, jumps to B (one second further along the path) and holds still
// again; the caster stands still. Per-frame RMSE of each lambda against the 256-tap reference at
// B (shadows_convergence.json), PCF 4 / 16 as flat lines; then the fig. 6.9 options at B.
void runConvergence(const Options& options, std::vector<std::unique_ptr<ShadowRenderer>>& renderers, const float* sweep,
                    std::vector<Record>& records, const demo::FlyPath& path, const glm::dmat4& projection) {
    const int w = options.width, h = options.height;
    auto viewAt = [&](double t) { const demo::Pose p = path.at(t); return glm::lookAt(p.position, p.target, p.up); };
    const glm::dmat4 caster = casterModel(5.0);
    uint32_t frameNumber = 100000;
    auto frame = [&](const glm::dmat4& view) {
        return ShadowFrame{.view = view, .projection = projection, .toLight = sunDirection(), .caster = caster,
                           .prevCaster = caster, .frame = frameNumber++};
    };
    const glm::dmat4 a = viewAt(6.0), b = viewAt(7.0);
    const int settle = options.smoke ? 3 : 6, after = options.smoke ? 5 : 12;
    // A clean start: what the moving sequence left in the caches (the caster's old shadows)
    // would otherwise fade during the measurement and blur what it shows.
    for (auto& r : renderers) r->cache().invalidate();
    for (int f = 0; f < settle; ++f)
        for (size_t i = 0; i < 4; ++i) renderers[i]->render(Variant::Amortized, {.lambda = sweep[i]}, frame(a));
    renderers[0]->render(Variant::Pcf, {.taps = 256}, frame(b));
    const Pixels reference = readRgba8(renderers[0]->color(Variant::Pcf), w, h);
    std::map<std::string, std::vector<double>> series;
    for (int taps : {4, 16}) {
        double e2 = 0;
        for (int f = 0; f < 4; ++f) {
            renderers[0]->render(Variant::Pcf, {.taps = taps}, frame(b));
            const double e = rmse(readRgba8(renderers[0]->color(Variant::Pcf), w, h), reference);
            e2 += e * e / 4;
        }
        series["pcf" + std::to_string(taps)] = std::vector<double>(after, std::sqrt(e2));
    }
    for (int f = 0; f < after; ++f)
        for (size_t i = 0; i < 4; ++i) {
            renderers[i]->render(Variant::Amortized, {.lambda = sweep[i]}, frame(b));
            char name[32];
            std::snprintf(name, sizeof name, "amortized_l%.2f", sweep[i]);
            series[name].push_back(rmse(readRgba8(renderers[i]->color(Variant::Amortized), w, h), reference));
        }
    writeSeries(options, "shadows_convergence.json", series);
    // Fig. 6.9 (e): blur + smoothstep remap, (f): threshold, both on the converged cache at B.
    Record& amortized = *std::find_if(records.begin(), records.end(), [](const Record& r) { return r.variant == "amortized"; });
    const std::tuple<Remap, const char*, const char*> figure69[] = {
        {Remap::None, "blurred (depth-aware)", "shadows_amortized_blur.png"},
        {Remap::Smoothstep, "blurred + smoothstep (fig. 6.9e)", "shadows_amortized_smoothstep.png"},
        {Remap::Threshold, "blurred + threshold (fig. 6.9f)", "shadows_amortized_threshold.png"}};
    for (auto [remap, label, file] : figure69) {
        if (options.smoke) break;   // CI's preset: the images are not worth its time
        for (int f = 0; f < 4; ++f) renderers[0]->render(Variant::Amortized, {.lambda = sweep[0], .blur = true, .remap = remap}, frame(b));
        amortized.images[label] = savePng(options, renderers[0]->color(Variant::Amortized), file);
        if (remap == Remap::None)
            amortized.extra["rmse_blurred_static"] = rmse(readRgba8(renderers[0]->color(Variant::Amortized), w, h), reference);
    }
    char mainSeries[32];
    std::snprintf(mainSeries, sizeof mainSeries, "amortized_l%.2f", sweep[0]);
    amortized.extra["rmse_converged_static"] = series[mainSeries].back();
    amortized.extra["rmse_pcf4_static"] = series["pcf4"].front();
    amortized.extra["rmse_pcf16_static"] = series["pcf16"].front();
}

// The control flows of docs/shadows.md side by side (a few interleaved frames of the sequence):
// PCF 4 without / with depth prepass, amortized single-pass / OnePass / TwoPass.
void compareFlows(const Options& options, ShadowRenderer& renderer, const std::function<ShadowFrame(int)>& frameAt, Record& amortized) {
    struct Case { const char* key; Variant variant; Flow flow; Tally tally; };
    Case cases[] = {{"ms_pcf4_no_prepass", Variant::Pcf, Flow::SinglePass, {}}, {"ms_pcf4_prepass", Variant::Pcf, Flow::OnePass, {}},
                    {"ms_flow_single_pass", Variant::Amortized, Flow::SinglePass, {}},
                    {"ms_flow_one_pass", Variant::Amortized, Flow::OnePass, {}},
                    {"ms_flow_two_pass", Variant::Amortized, Flow::TwoPass, {}}};
    const int frames = options.smoke ? 2 : 6;
    for (int f = -2; f < frames; ++f)
        for (Case& c : cases) {
            const ShadowFrame frame = frameAt(1000 + f);
            const double ms = timeOnce([&] {
                renderer.invalidateShadowMap();
                renderer.render(c.variant, {.taps = 4, .flow = c.flow}, frame);
            });
            if (f >= 0) c.tally.ms.push_back(ms);
        }
    for (Case& c : cases) amortized.extra[c.key] = c.tally.timing().median;
}

std::vector<Record> runShadows(const Options& options, ShaderLibrary& library) {
    const auto loaded = loadBenchScene(options.scene);
    if (!loaded) return {};
    const BenchScene& scene = *loaded;
    library.add(demo::commonShaders());
    const int w = options.width, h = options.height;
    // Renderer i amortizes with sweep[i]; the main row's lambda, 0.75, has the lowest RMSE on the
    // moving sequence (the sweep: 0.0159 / 0.0121 / 0.0100 / 0.0104 for 0.4 / 0.6 / 0.75 / 0.9).
    const float sweep[] = {0.75f, 0.4f, 0.6f, 0.9f};
    std::vector<std::unique_ptr<ShadowRenderer>> renderers;
    // 0-3: the lambdas of `sweep`, with the chapter's plain recursive filter and no stats target
    // (each saves a fetch or a write per pixel: docs/shadows.md); 4: amortized + blur, with both,
    // which also gives the hit rate (every variant follows the same camera path).
    // 5: the flow comparison, as 0-3 plus the stencil the two-pass flow needs.
    for (int i = 0; i < 6; ++i) {
        renderers.push_back(std::make_unique<ShadowRenderer>());
        const CacheFeatures features{.age = i == 4, .stats = i == 4, .stencil = i == 5};
        if (auto r = renderers.back()->init(w, h, library, scene.draws, scene.boundsMin, scene.boundsMax, 2048, features); !r) return {};
    }
    // The blur row keeps lambda 0.6: the blur already averages over space, and with 0.75 on top
    // its RMSE rose from 0.0101 to 0.0120 (measured).
    std::vector<Run> runs = {{"pcf", 4, -1, 0, {}}, {"pcf", 16, -1, 0, {}}, {"amortized", 4, sweep[0], 0, {}}, {"amortized + blur", 4, 0.6f, 4, {}, true},
                             {"amortized (lambda sweep)", 4, sweep[1], 1, {}}, {"amortized (lambda sweep)", 4, sweep[2], 2, {}},
                             {"amortized (lambda sweep)", 4, sweep[3], 3, {}}};
    const glm::dmat4 projection = demo::perspective(0.9, double(w) / h, 0.1);
    const demo::FlyPath path = cameraPath({scene.boundsMin, scene.boundsMax});
    auto frameAt = [&](int f, double t, const glm::dmat4& view) {
        return ShadowFrame{.view = view, .projection = projection, .toLight = sunDirection(), .caster = casterModel(t),
                           .prevCaster = casterModel(t - 1.0 / 60.0), .frame = uint32_t(f)};
    };
    auto viewAt = [&](double t) { const demo::Pose p = path.at(t); return glm::lookAt(p.position, p.target, p.up); };
    const double t0 = 4.0;   // a stretch of the path with columns, floor and the caster in view
    auto render = [&](const Run& run, const ShadowFrame& frame) {
        renderers[run.renderer]->invalidateShadowMap();   // the caster moved: every variant re-renders it
        renderers[run.renderer]->render(run.lambda < 0 ? Variant::Pcf : Variant::Amortized,
                                        {.taps = run.taps, .lambda = std::max(run.lambda, 0.0f), .blur = run.blur, .seed = 1}, frame);
    };
    const Run reference{"reference", 256, -1, 0, {}};
    // Half the common frame count: 6-8 variants per frame and the sweeps must fit the demos'
    // share of scripts/demo's time; the reference (256 samples) on every 5th frame.
    const int frames = std::max(2, options.frames / 2);
    const int checkEvery = std::max(1, std::min(5, frames / 3));
    Tally referenceTally;
    double hits = 0, lookups = 0;
    std::fprintf(stderr, "shadows: %d frames x %zu variants, interleaved; reference every %d frames (load %s)\n", frames,
                 runs.size(), checkEvery, loadAverage().c_str());
    Pixels referencePixels;
    for (int f = -options.warmup; f < frames; ++f) {
        const double t = t0 + (f + options.warmup) / 60.0;
        const ShadowFrame frame = frameAt(f + options.warmup, t, viewAt(t));
        const bool check = f >= 0 && f % checkEvery == 0;
        if (check) {
            referenceTally.ms.push_back(timeOnce([&] { render(reference, frame); }));
            referencePixels = readRgba8(renderers[0]->color(Variant::Pcf), w, h);
        }
        for (Run& run : runs) {
            const double ms = timeOnce([&] { render(run, frame); });
            if (f < 0) continue;
            run.tally.ms.push_back(ms);
            ShadowRenderer& r = *renderers[run.renderer];
            if (check) run.tally.addError(rmse(readRgba8(r.color(run.lambda < 0 ? Variant::Pcf : Variant::Amortized), w, h), referencePixels));
            if (check && run.renderer == 4) {
                const Stats s = r.cache().finishStats();
                hits += double(s.hits);
                lookups += double(s.hits + s.misses + s.forced + s.refreshed);
            }
        }
    }
    // Sample frames: the last frame of the sequence, every variant and the reference.
    std::vector<Record> records;
    const int last = frames + options.warmup - 1;
    const double tLast = t0 + last / 60.0;
    const ShadowFrame lastFrame = frameAt(last, tLast, viewAt(tLast));
    render(reference, lastFrame);
    const Pixels refLast = readRgba8(renderers[0]->color(Variant::Pcf), w, h);
    Record ref{.demo = "shadows", .variant = "reference", .samples = 256, .width = w, .height = h, .frames = int(referenceTally.ms.size())};
    ref.timing = referenceTally.timing();
    ref.rmse = 0.0;
    ref.psnr = INFINITY;
    ref.images["256-tap PCF"] = savePng(options, renderers[0]->color(Variant::Pcf), "shadows_reference.png");
    for (Run& run : runs) {
        Record r{.demo = "shadows", .variant = run.variant, .samples = run.taps, .width = w, .height = h, .frames = frames};
        if (run.lambda >= 0) r.lambda = run.lambda;
        r.timing = run.tally.timing();
        r.rmse = run.tally.rmse();
        r.psnr = psnr(*r.rmse);
        const std::string stem = "shadows_" + std::string(run.lambda < 0 ? "pcf" : "amortized") + std::to_string(run.taps) +
                                 (run.lambda >= 0 ? "_l" + std::to_string(int(run.lambda * 100 + 0.5)) : "");
        if ((run.lambda >= 0 && run.renderer == 0) || run.lambda < 0) {
            // The last frame was rendered in the loop; render it again only for the PCF variants
            // (their image is overwritten by the next variant), the cache state stays as it was.
            if (run.lambda < 0) render(run, lastFrame);
            const GLuint color = renderers[run.renderer]->color(run.lambda < 0 ? Variant::Pcf : Variant::Amortized);
            r.images["frame"] = savePng(options, color, stem + ".png");
            saveRgba8Difference(options, readRgba8(color, w, h), refLast, w, h, 4.0f, stem + "_diff.png", r, "difference x4");
        }
        if (run.lambda >= 0 && run.renderer == 0) {
            r.hitRate = lookups > 0 ? hits / lookups : 0.0;
            Texture vis;
            renderers[4]->cache().visualize(vis);
            r.images["hits (green) / misses (red)"] = savePng(options, vis.id(), stem + "_hits.png");
        }
        std::fprintf(stderr, "shadows %-26s k=%3d lambda %.2f  median %7.2f ms  min %7.2f ms  RMSE %.5f\n", run.variant, run.taps,
                     std::max(run.lambda, 0.0f), r.timing.median, r.timing.min, *r.rmse);
        records.push_back(std::move(r));
    }
    records.push_back(std::move(ref));
    Record& amortized = *std::find_if(records.begin(), records.end(), [](const Record& r) { return r.variant == "amortized"; });
    if (!options.smoke) compareFlows(options, *renderers[5], [&](int f) { const double t = t0 + f / 60.0; return frameAt(f, t, viewAt(t)); }, amortized);
    runConvergence(options, renderers, sweep, records, path, projection);
    return records;
}

} // namespace
} // namespace rrc::bench
