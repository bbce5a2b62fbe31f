// rrc-bench's stereo rows: brute force against the view-independent and view-dependent cached
// variants over one deterministic camera path; error of the left eye against brute force's.
#include "bench_scenes.hpp"

#include "stereo/stereo_renderer.hpp"

#include "common/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <rrc/projection.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace rrc::bench {
namespace {

using stereo::Variant;

// The fly-through down the colonnade (demos/common/camera.hpp), on the fixed 60 Hz clock.
glm::dmat4 pathView(const demo::FlyPath& path, int frame) {
    const demo::Pose pose = path.at(frame / 60.0);
    return glm::lookAt(pose.position, pose.target, pose.up);
}

std::vector<Record> runStereo(const Options& options, ShaderLibrary& library);
const DemoRegistration registration{"stereo", 0, runStereo};

std::vector<Record> runStereo(const Options& options, ShaderLibrary& library) {
    const auto loaded = loadBenchScene(options.scene);
    if (!loaded) return {};
    const BenchScene& scene = *loaded;
    std::fprintf(stderr, "stereo: scene %s\n", scene.name.c_str());
    stereo::StereoRenderer renderer;
    renderer.setFlow(options.cachedFlow(), options.probe());   // before init: it decides the caches' stencil
    if (auto r = renderer.init(options.width, options.height, library); !r) return {};
    const glm::dmat4 projection = perspectiveReversedZ(0.9, double(options.width) / options.height, 0.1);
    const double separation = options.eyeSeparation;
    const demo::FlyPath path = demo::FlyPath::colonnade({scene.boundsMin, scene.boundsMax});
    const Variant variants[] = {Variant::Brute, Variant::Cached, Variant::CachedViewDependent};
    // The variants take turns on every frame of the path, so that anything else the machine does
    // weighs on all of them alike: their ratios are measured side by side.
    struct Tally {
        std::vector<double> ms;
        double error2 = 0, specError2 = 0, hits = 0, total = 0;
        long pixels = 0, specPixels = 0;
    } tally[3];
    const int checkEvery = std::max(1, options.frames / 4);   // left eyes compared with brute force
    std::fprintf(stderr, "stereo: %d frames x 3 variants, interleaved\n", options.frames);
    for (int f = -options.warmup; f < options.frames; ++f) {
        const auto eyes = stereo::eyeViews(pathView(path, std::max(f, 0)), projection, separation);
        OIIO::ImageBuf reference, referenceSpecular;
        for (int v = 0; v < 3; ++v) {
            glFinish();
            const auto t0 = std::chrono::steady_clock::now();
            renderer.render(variants[v], eyes, scene.draws);
            glFinish();
            const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (f < 0) continue;
            Tally& t = tally[v];
            t.ms.push_back(elapsed);
            if (f % checkEvery != 0) continue;
            OIIO::ImageBuf left = readTexture(renderer.leftEye(variants[v]));
            if (variants[v] == Variant::Brute) {
                reference = left;
                referenceSpecular = readTexture(renderer.specularMask());
                continue;
            }
            const ErrorStats e = errorAgainst(left, reference);
            t.error2 += e.rmse * e.rmse * double(e.pixels);
            t.pixels += e.pixels;
            const ErrorStats sp = errorAgainst(left, reference, &referenceSpecular, 0.05f);
            t.specError2 += sp.rmse * sp.rmse * double(sp.pixels);
            t.specPixels += sp.pixels;
            const Stats st = renderer.cache(variants[v]).finishStats();
            t.hits += double(st.hits);
            t.total += double(st.hits + st.misses + st.forced + st.refreshed);
        }
    }
    std::vector<Record> records;
    double bruteMedian = 0;
    for (int v = 0; v < 3; ++v) {
        const Variant variant = variants[v];
        Tally& t = tally[v];
        Record r{.demo = "stereo", .variant = stereo::variantName(variant), .width = options.width, .height = options.height,
                 .frames = options.frames};
        std::sort(t.ms.begin(), t.ms.end());
        r.timing = {t.ms[t.ms.size() / 2], t.ms.front(), options.frames};
        // Sample frames of the last view of the path, rendered again by this variant.
        const auto eyes = stereo::eyeViews(pathView(path, options.frames - 1), projection, separation);
        renderer.render(variant, eyes, scene.draws);
        const std::string prefix = "stereo_" + r.variant;
        r.images["anaglyph"] = savePng(options, renderer.anaglyph(), prefix + "_anaglyph.png");
        r.images["left eye"] = savePng(options, renderer.leftEye(variant), prefix + "_left.png");
        double lookupMs = 0;
        if (variant != Variant::Brute) {
            Texture vis;
            renderer.cache(variant).visualize(vis);
            r.images["hits (green) / misses (red) / forced (blue)"] = savePng(options, vis.id(), prefix + "_hits.png");
            r.images["difference x8"] = saveDifference(options, readTexture(renderer.leftEye(variant)),
                                                       readTexture(renderer.leftEye(Variant::Brute)), 8.0f, prefix + "_diff.png");
            // The lookup's own cost: the left eye again over a cache holding that same view.
            lookupMs = demo::timeFrames([&] { renderer.renderLeftAgain(variant, eyes, scene.draws); }, 2, 5).median;
        }
        if (variant == Variant::Brute) {
            bruteMedian = r.timing.median;
            r.rmse = 0.0;
            r.psnr = INFINITY;
            r.speedup = 1.0;
        } else {
            r.rmse = std::sqrt(t.error2 / std::max(1L, t.pixels));
            r.psnr = *r.rmse > 0 ? 20 * std::log10(1.0 / *r.rmse) : INFINITY;
            const double specRmse = std::sqrt(t.specError2 / std::max(1L, t.specPixels));
            r.extra["psnr_specular"] = specRmse > 0 ? 20 * std::log10(1.0 / specRmse) : INFINITY;
            r.hitRate = t.total > 0 ? t.hits / t.total : 0.0;
            r.speedup = bruteMedian / r.timing.median;
            // Best case for this run: the right eye in full, the left eye at the measured lookup
            // cost plus full shading for the measured miss fraction.
            const double eye = bruteMedian / 2;
            r.bestSpeedup = bruteMedian / (eye + lookupMs + (1.0 - *r.hitRate) * eye);
            r.extra["lookup_ms"] = lookupMs;
        }
        std::fprintf(stderr, "stereo %-22s median %7.2f ms  min %7.2f ms", r.variant.c_str(), r.timing.median, r.timing.min);
        if (variant != Variant::Brute)
            std::fprintf(stderr, "  PSNR %.1f dB (specular %.1f dB)  hit rate %.3f  x%.2f", *r.psnr, r.extra["psnr_specular"],
                         *r.hitRate, *r.speedup);
        std::fprintf(stderr, "\n");
        records.push_back(std::move(r));
    }
    return records;
}

} // namespace
} // namespace rrc::bench
