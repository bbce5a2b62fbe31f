// rrc-bench, the main job: every demo's brute-force and cached variants over the same
// deterministic camera path, timed (median and min over the measured frames after warm-up) and
// compared with the reference. Writes out/results.json (and run.json) and the sample frames;
// scripts/make-report.py turns them into out/results.csv, plots and out/report.md.
#include "bench_scenes.hpp"

#include <rrc/context.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>

namespace {
std::vector<std::string> splitList(const std::string& list) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = std::min(list.find(',', start), list.size());
        if (comma > start) items.push_back(list.substr(start, comma - start));
        start = comma + 1;
    }
    return items;
}
} // namespace

int main(int argc, char** argv) {
    using namespace rrc;
    CLI::App app{"rrc-bench: brute force against the reprojection cache, time against error"};
    bench::Options o;
    std::string backendOption = "auto", size = "1024x768", demos = "all";
    app.add_option("--out", o.outDir, "output folder")->default_val("out");
    app.add_option("--backend", backendOption, "auto, egl, osmesa or glfw")->default_val("auto");
    app.add_option("--size", size, "frame size WxH")->default_val("1024x768");
    app.add_option("--frames", o.frames,
                   "measured frames per variant (stereo; shadows and bump_env take half; motion blur and depth of field "
                   "time fixed frames of their sweeps)")->check(CLI::Range(1, 100000));
    app.add_option("--warmup", o.warmup, "unmeasured frames first (stereo, shadows, bump_env)")->check(CLI::Range(0, 1000));
    app.add_option("--scene", o.scene, "glTF scene, or 'procedural' (stereo, shadows; the other demos have their own)")
        ->default_val("assets/temple.glb");
    std::string known;
    for (const auto& d : bench::registeredDemos()) known += (known.empty() ? "" : ", ") + d.name;
    app.add_option("--demos", demos, "comma-separated demos to run (" + known + "), or all")->default_val("all");
    app.add_option("--eye-separation", o.eyeSeparation, "stereo: distance between the eyes, scene units")->default_val(0.065);
    app.add_option("--flow", o.flow, "cached control flow")->check(CLI::IsMember(demo::kFlowNames))->default_val("one-pass");
    app.add_flag("--smoke", o.smoke, "small and quick: 256x192, few frames (CI)");
    app.add_flag("--full", o.full, "longer runs and sweeps");
    CLI11_PARSE(app, argc, argv);
    if (std::sscanf(size.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width <= 0 || o.height <= 0) {
        std::fprintf(stderr, "rrc-bench: --size must be WxH, got '%s'\n", size.c_str());
        return 1;
    }
    if (o.smoke) { o.width = 256; o.height = 192; o.frames = std::min(o.frames, 6); o.warmup = std::min(o.warmup, 2); }
    if (o.full) o.frames = std::max(o.frames, 60);
    auto backend = parseBackend(backendOption);
    if (!backend) return 1;
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec) { std::fprintf(stderr, "rrc-bench: cannot create %s: %s\n", o.outDir.c_str(), ec.message().c_str()); return 1; }
    auto context = Context::create({.backend = backend.value(), .width = o.width, .height = o.height, .visible = false});
    if (!context) return 1;
    std::fprintf(stderr, "rrc-bench: %dx%d, %d frames after %d warm-up, %s on %s\n", o.width, o.height, o.frames, o.warmup,
                 std::string(backendName(context.value().backend())).c_str(), context.value().renderer().c_str());
    ShaderLibrary library;
    library.add(demo::supportShaders());
    library.add(bench::demoShaders());
    std::vector<bench::Record> records;
    const std::vector<std::string> wanted = splitList(demos);
    for (const std::string& name : wanted) {
        const auto& all = bench::registeredDemos();
        if (name != "all" && std::none_of(all.begin(), all.end(), [&](const auto& d) { return d.name == name; })) {
            std::fprintf(stderr, "rrc-bench: --demos: unknown demo '%s' (known: %s)\n", name.c_str(), known.c_str());
            return 1;
        }
    }
    for (const auto& d : bench::registeredDemos()) {
        if (std::find(wanted.begin(), wanted.end(), "all") == wanted.end() &&
            std::find(wanted.begin(), wanted.end(), d.name) == wanted.end())
            continue;
        const auto t0 = std::chrono::steady_clock::now();
        auto rows = d.run(o, library);
        if (rows.empty()) { std::fprintf(stderr, "rrc-bench: %s failed\n", d.name.c_str()); return 1; }
        std::fprintf(stderr, "rrc-bench: %s done in %.0f s\n", d.name.c_str(),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        records.insert(records.end(), rows.begin(), rows.end());
        bench::writeResults(o, records);   // partial results survive a later failure
    }
    bench::writeResults(o, records);
    std::ofstream meta(o.outDir + "/run.json");
    char date[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    meta << "{\"date\": \"" << date << "\", \"command\": \"" << command << "\", \"renderer\": \"" << context.value().renderer()
         << "\", \"backend\": \"" << backendName(context.value().backend()) << "\", \"width\": " << o.width
         << ", \"height\": " << o.height << ", \"frames\": " << o.frames << ", \"warmup\": " << o.warmup << "}\n";
    std::fprintf(stderr, "rrc-bench: wrote %s/results.json\n", o.outDir.c_str());
    return 0;
}
