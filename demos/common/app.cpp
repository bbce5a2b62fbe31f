// runDemo(): context, init, the headless loop on a fixed clock (t = frame / 60 s), timing with
// glFinish around each frame, image output and the JSON report. The window loop is in
// app_window.cpp, the command line in app_options.cpp.
#include "app_internal.hpp"
#include "fullscreen.hpp"

#include <rrc/debug.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>

namespace rrc::demo {

std::string_view modeName(Mode mode) { return mode == Mode::Brute ? "brute" : "cached"; }

int runDemo(int argc, char** argv, DemoDesc desc) {
    CLI::App cli{"rrc demo: " + desc.name, desc.name};
    Options options;
    if (auto exit = parseCommandLine(argc, argv, cli, options, desc)) return *exit;
    return Runner(std::move(desc), std::move(options), cli).run();
}

Runner::Runner(DemoDesc desc, Options options, const CLI::App& cli) : desc_(std::move(desc)), cli_(cli) {
    app_.options_ = std::move(options);
    app_.width_ = app_.options_.width;
    app_.height_ = app_.options_.height;
    app_.mode_ = app_.options_.mode;
}

int Runner::run() {
    const Options& o = app_.options_;
    auto context = Context::create({.backend = o.backend, .width = o.width, .height = o.height,
                                    .title = "rrc: " + desc_.name, .visible = true});
    if (!context) {
        std::fprintf(stderr, "%s: cannot create a GL context: %s\n", desc_.name.c_str(), context.error().message.c_str());
        return 2;
    }
    app_.context_ = &context.value();
    app_.window_ = context.value().window();
    app_.shaders_.add(commonShaders());
    checkGLErrors("before demo init");
    resetDebugCounters();

    Result<void> result = desc_.init ? desc_.init(app_) : Result<void>();
    if (result) result = app_.windowed() ? runWindowed() : runHeadless();
    if (result) {
        if (desc_.stats) stats_ = desc_.stats(app_);
        if (!o.out.empty()) {
            auto written = writeOutputs(o.out, desc_.name, desc_.outputs ? desc_.outputs(app_) : Outputs{});
            if (written) written_.update(written.value());
            else result = written.error();
        }
    }
    glErrors_ = checkGLErrors("demo " + desc_.name) + debugCounters().glErrors + debugCounters().debugErrors;
    if (desc_.cleanup) desc_.cleanup(app_);   // also after a failed init: frees what it made
    if (!result) {
        std::fprintf(stderr, "%s: %s\n", desc_.name.c_str(), result.error().message.c_str());
        return 2;
    }
    if (o.json) std::printf("%s\n", report().dump().c_str());
    std::fflush(stdout);
    return 0;
}

Result<void> Runner::runHeadless() {
    const Options& o = app_.options_;
    for (int frame = 0; frame < o.warmup + o.frames; ++frame) {
        timedFrame({.frame = frame, .time = frame / 60.0, .dt = 1.0 / 60.0, .warmup = frame < o.warmup});
    }
    return {};
}

Result<void> Runner::resize(int width, int height) {
    if (width == app_.width_ && height == app_.height_) return {};
    app_.width_ = width;
    app_.height_ = height;
    return desc_.onResize ? desc_.onResize(app_, width, height) : Result<void>();
}

double Runner::timedFrame(const FrameInfo& info) {
    if (app_.followsPath()) app_.path_(info.time).applyTo(app_.camera_);
    glFinish();   // nothing of earlier frames (or of the overlay) is charged to this one
    const auto start = std::chrono::steady_clock::now();
    if (desc_.frame) desc_.frame(app_, info);
    glFinish();
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    if (!info.warmup) frameMs_.push_back(elapsed.count());
    ++framesRendered_;
    return elapsed.count();
}

nlohmann::json Runner::report() const {
    nlohmann::json timings;
    timings["frames"] = frameMs_.size();
    timings["warmup"] = app_.options_.warmup;
    timings["frame_ms"] = frameMs_;
    if (frameMs_.empty()) {
        timings["ms_median"] = timings["ms_min"] = timings["ms_mean"] = nullptr;
    } else {
        std::vector<double> sorted = frameMs_;
        std::sort(sorted.begin(), sorted.end());
        const size_t n = sorted.size();
        timings["ms_median"] = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        timings["ms_min"] = sorted.front();
        timings["ms_mean"] = std::accumulate(sorted.begin(), sorted.end(), 0.0) / static_cast<double>(n);
    }
    nlohmann::json r;
    r["demo"] = desc_.name;
    r["backend"] = backendName(app_.context_->backend());
    r["renderer"] = app_.context_->renderer();
    r["width"] = app_.width_;
    r["height"] = app_.height_;
    r["mode"] = modeName(app_.mode_);
    r["ms_median"] = timings["ms_median"];
    r["ms_min"] = timings["ms_min"];
    r["frames"] = frameMs_.size();
    r["frames_rendered"] = framesRendered_;
    r["timings"] = timings;
    r["options"] = optionsJson(cli_);
    r["stats"] = nlohmann::json(stats_);
    r["outputs"] = written_;
    r["gl_errors"] = glErrors_;
    r["windowed"] = app_.windowed();
    r["gui_frames"] = guiFrames_;
    const Camera& c = app_.camera_;
    r["camera"] = {{"position", {c.position.x, c.position.y, c.position.z}},
                   {"forward", {c.forward().x, c.forward().y, c.forward().z}},
                   {"follows_path", app_.followsPath()}};
    return r;
}

} // namespace rrc::demo
