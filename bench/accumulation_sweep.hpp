// What rrc-bench's motion_blur and depth_of_field rows share: a sweep of the sample count N over
// "arms" (brute force, cached, ...) against a brute-force reference with many samples. The arms
// take turns at every (frame, N), so anything else the machine does weighs on all of them alike.
// Header-only: bench/CMakeLists.txt compiles only bench/*_bench.cpp.
#pragma once
#include "bench_scenes.hpp"

#include "accumulation/accumulation_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>

namespace rrc::bench::accumulation_sweep {

using accumulation::Variant;

struct Arm {
    std::string name;               // results.json "variant"
    Variant variant = Variant::Cached;
    std::vector<int> samples;       // the N this arm is measured at
    // Renders one output frame (time in seconds) with n samples into renderer.result().
    std::function<void(int n, double time, bool trackHits)> render;
};

struct Sweep {
    std::string demo;
    std::vector<Arm> arms;          // arms[0] renders the reference too (brute force)
    int referenceSamples = 64;
    std::vector<double> frameTimes;
    int imageSamples = 8;           // sample images of every arm at this N (and at equal time)
};

inline double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

inline double timed(const std::function<void()>& f) {
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    glFinish();
    return msSince(t0);
}

inline std::vector<Record> run(const Options& options, accumulation::AccumulationRenderer& renderer, const Sweep& sweep) {
    struct Tally { std::vector<double> ms; double error2 = 0; long pixels = 0; };
    std::map<std::pair<size_t, int>, Tally> tally;   // (arm, N)
    std::vector<double> referenceMs;
    std::set<int> allSamples;
    for (const Arm& a : sweep.arms) allSamples.insert(a.samples.begin(), a.samples.end());
    // Warm-up: every program of every arm JIT-compiled once (tens of ms each on llvmpipe).
    for (const Arm& a : sweep.arms) a.render(2, sweep.frameTimes.front(), false);
    OIIO::ImageBuf reference;
    for (double time : sweep.frameTimes) {
        referenceMs.push_back(timed([&] { sweep.arms[0].render(sweep.referenceSamples, time, false); }));
        reference = readTexture(renderer.result());
        for (int n : allSamples) {
            for (size_t a = 0; a < sweep.arms.size(); ++a) {
                const Arm& arm = sweep.arms[a];
                if (std::find(arm.samples.begin(), arm.samples.end(), n) == arm.samples.end()) continue;
                Tally& t = tally[{a, n}];
                t.ms.push_back(timed([&] { arm.render(n, time, false); }));
                const ErrorStats e = errorAgainst(readTexture(renderer.result()), reference);
                t.error2 += e.rmse * e.rmse * double(e.pixels);
                t.pixels += e.pixels;
            }
        }
        std::fprintf(stderr, "%s: frame at t=%.3f s done\n", sweep.demo.c_str(), time);
    }
    auto median = [](std::vector<double> v) {   // of an even count: the mean of the middle two
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    };
    const int frames = int(sweep.frameTimes.size());
    const double lastTime = sweep.frameTimes.back();
    std::vector<Record> records;
    Record ref{.demo = sweep.demo, .variant = "reference", .samples = sweep.referenceSamples, .width = options.width,
               .height = options.height, .frames = frames};
    ref.timing = {median(referenceMs), *std::min_element(referenceMs.begin(), referenceMs.end()), frames};
    ref.rmse = 0.0;
    ref.psnr = INFINITY;
    ref.images["reference"] = savePng(options, renderer.result(), sweep.demo + "_reference.png");
    records.push_back(ref);
    double bruteAt8 = 0;
    for (size_t a = 0; a < sweep.arms.size(); ++a) {
        const Arm& arm = sweep.arms[a];
        for (int n : arm.samples) {
            Tally& t = tally[{a, n}];
            Record r{.demo = sweep.demo, .variant = arm.name, .samples = n, .width = options.width, .height = options.height,
                     .frames = frames};
            r.timing = {median(t.ms), *std::min_element(t.ms.begin(), t.ms.end()), frames};
            r.rmse = std::sqrt(t.error2 / double(std::max(1L, t.pixels)));
            r.psnr = *r.rmse > 0 ? 20 * std::log10(1.0 / *r.rmse) : INFINITY;
            r.extra["ms_per_sample"] = r.timing.median / n;
            if (arm.variant == Variant::Brute && n == 8) bruteAt8 = r.timing.median;
            const bool image = n == sweep.imageSamples;
            if (arm.variant == Variant::Cached || image) {
                // Hit rate (untimed: waiting for every sample's statistics stalls the pipeline)
                // and, at the image N, sample frames of the last frame time.
                arm.render(n, lastTime, arm.variant == Variant::Cached);
                if (arm.variant == Variant::Cached && renderer.settings().stats) r.hitRate = renderer.hitRate();
                if (image) {
                    const std::string stem = sweep.demo + "_" + arm.name + "_n" + std::to_string(n);
                    r.images["frame"] = savePng(options, renderer.result(), stem + ".png");
                    r.images["difference from the reference x4"] =
                        saveDifference(options, readTexture(renderer.result()), reference, 4.0f, stem + "_diff.png");
                    if (arm.variant == Variant::Cached && renderer.settings().stats) {
                        Texture vis;
                        renderer.cache().visualize(vis);
                        r.images["last sample: hits (green) / misses (red)"] = savePng(options, vis.id(), stem + "_hits.png");
                    }
                }
            }
            records.push_back(std::move(r));
        }
    }
    std::map<int, double> bruteMs;
    for (const Record& r : records)
        if (r.variant == sweep.arms[0].name) bruteMs[r.samples] = r.timing.median;
    for (Record& r : records) {
        if (r.variant == "reference") continue;
        if (bruteMs.count(r.samples)) r.speedup = bruteMs[r.samples] / r.timing.median;   // brute force, same N
        r.extra["time_vs_brute_n8"] = bruteAt8 > 0 ? r.timing.median / bruteAt8 : 0.0;  // for the equal-time table
        std::fprintf(stderr, "%s %-14s N=%2d  median %8.1f ms  min %8.1f ms  RMSE %.5f  PSNR %5.2f dB", sweep.demo.c_str(),
                     r.variant.c_str(), r.samples, r.timing.median, r.timing.min, *r.rmse, *r.psnr);
        if (r.hitRate) std::fprintf(stderr, "  hit rate %.3f", *r.hitRate);
        std::fprintf(stderr, "\n");
    }
    return records;
}

} // namespace rrc::bench::accumulation_sweep
