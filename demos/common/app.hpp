// The app skeleton every demo runs on (sokol_app style): a DemoDesc of callbacks goes into
// runDemo(), which parses the common command line, creates the context (windowed GLFW or headless
// EGL/OSMesa), steps the frames, times them and writes images and a JSON report.
#pragma once
#include "camera.hpp"

#include <rrc/context.hpp>
#include <rrc/shader.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <string>

namespace CLI { class App; }

namespace rrc::demo {

enum class Mode { Brute, Cached };
std::string_view modeName(Mode mode);   // "brute", "cached"

// The common command line (defaults as listed; all validated before any GL work):
//   --backend auto|egl|osmesa|glfw  auto: RRC_GL_BACKEND, else GLFW if a display works, else EGL,
//                                   else OSMesa
//   --size WxH       1024x768       render size (and initial window size)
//   --frames N       60             measured frames; windowed runs until closed unless given
//   --warmup N       5              frames rendered before the measured ones
//   --mode brute|cached  cached
//   --scene FILE     ""             must exist; empty = the demo's default scene
//   --out DIR        ""             writes <name>.png, <name>.exr (+ <name>_hitmiss.png) of the last
//                                   frame; in a window with --frames also <name>_window.png (overlay)
//   --json                          prints one JSON object on stdout (see report fields below)
//   --seed N         1
struct Options {
    Backend backend = Backend::Auto;
    int width = 1024;
    int height = 768;
    int frames = 60;
    bool framesGiven = false;      // --frames was on the command line
    int warmup = 5;
    Mode mode = Mode::Cached;
    std::string scene;
    std::string out;
    bool json = false;
    uint32_t seed = 1;
};

struct FrameInfo {
    int frame = 0;            // 0-based, warm-up frames included
    double time = 0.0;        // seconds: frame / 60 headless (fixed clock); wall clock windowed
    double dt = 1.0 / 60.0;   // seconds since the previous frame
    bool warmup = false;      // not timed
};

// What a demo shows and writes. Textures are read whole (level 0).
struct Outputs {
    GLuint color = 0;          // final colour: shown in the window, written as PNG + EXR
    GLuint visualization = 0;  // optional hit/miss view: V toggles it, written as <name>_hitmiss.png
};

using Stats = std::map<std::string, double>;   // e.g. {"hit_rate", 0.93}; JSON object "stats"

class App;

// Every callback except `frame` may be left empty. All run with the GL context current.
// `cleanup` runs whenever `init` ran (also after a failed init), before the context goes: drop
// every GL object there. A demo's main.cpp is one line:
//   int main(int argc, char** argv) { return rrc::demo::runDemo(argc, argv, {.name = "stereo", ...}); }
struct DemoDesc {
    std::string name = "demo";                          // window title, output file stem
    std::function<void(CLI::App&)> addOptions;          // the demo's own options (--lambda ...)
    std::function<Result<void>(App&)> init;             // failure ends the run (exit code 2)
    std::function<void(App&, const FrameInfo&)> frame;  // render one frame into the demo's targets
    std::function<Outputs(App&)> outputs;               // asked at the end (--out) and per window frame
    std::function<Stats(App&)> stats;                   // asked at the end (report) and per window frame
    std::function<void(App&)> gui;                      // windowed: ImGui widgets (sliders ...)
    std::function<Result<void>(App&, int width, int height)> onResize;  // render size changed
    std::function<void(App&)> cleanup;
};

// Runs the demo. Returns 0 on success, 1 for bad options (after printing the reason on stderr;
// --help prints usage and returns 0), 2 when the context, init, a resize or image output failed.
// Only the --json report goes to stdout, as one line:
//   {"demo", "backend" (the one used), "renderer", "width", "height" (final render size), "mode",
//    "ms_median", "ms_min", "frames" (measured), "frames_rendered", "timings": {"ms_median",
//    "ms_min", "ms_mean", "frames", "warmup", "frame_ms": [...]}, "options": {every option by long
//    name, the demo's included}, "stats": {...}, "outputs": {"png", "exr", "hitmiss_png",
//    "window_png"}, "gl_errors", "windowed", "gui_frames", "camera": {"position", "forward",
//    "follows_path"} (at the end)}
// Frame times are wall clock between glFinish calls around DemoDesc::frame (the blit and the
// overlay excluded); frames 0..warmup-1 are not measured.
int runDemo(int argc, char** argv, DemoDesc desc);

// The running demo's view of the app. Created by runDemo; demos only see references.
class App {
public:
    const Options& options() const { return options_; }
    int width() const { return width_; }       // current render size (follows the window)
    int height() const { return height_; }
    double aspect() const { return static_cast<double>(width_) / height_; }
    Mode mode() const { return mode_; }        // M toggles it in the window
    void setMode(Mode mode) { mode_ = mode; }
    bool showVisualization() const { return showVisualization_; }   // V toggles it
    uint32_t seed() const { return options_.seed; }
    const std::string& scenePath() const { return options_.scene; }
    bool windowed() const { return window_ != nullptr; }
    GLFWwindow* window() const { return window_; }                  // null headless
    Context& context() { return *context_; }
    ShaderLibrary& shaders() { return shaders_; }                   // rrc/ and common/ files
    Camera& camera() { return camera_; }

    // The camera follows `path` (evaluated at FrameInfo::time before each frame) headless, and in
    // the window until the user flies; C returns to it.
    void setCameraPath(CameraPath path) { path_ = std::move(path); followPath_ = true; }
    bool followsPath() const { return path_ && followPath_; }

private:
    friend class Runner;
    Options options_;
    int width_ = 0, height_ = 0;
    Mode mode_ = Mode::Cached;
    bool showVisualization_ = false;
    GLFWwindow* window_ = nullptr;
    Context* context_ = nullptr;
    ShaderLibrary shaders_;
    Camera camera_;
    CameraPath path_;
    bool followPath_ = true;
};

} // namespace rrc::demo
