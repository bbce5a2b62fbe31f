// Internal to rrc_demo_common: the runner behind runDemo(), shared by the headless loop
// (app.cpp), the window loop (app_window.cpp) and the command line and report (app_options.cpp).
#pragma once
#include "app.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace rrc::demo {

// Parses "WxH" (each 1..16384); nullopt otherwise.
std::optional<std::pair<int, int>> parseSize(std::string_view text);

// Declares the common options and the demo's, then parses. Returns the exit code when the run
// must stop here (0 after --help, 1 for a bad option, the reason already on stderr).
std::optional<int> parseCommandLine(int argc, char** argv, CLI::App& cli, Options& options,
                                    const DemoDesc& desc);
// Every option of `cli` (common and the demo's) with its value or default, by long name.
nlohmann::json optionsJson(const CLI::App& cli);

// Reads the output textures and writes <dir>/<name>.png, .exr and <name>_hitmiss.png; returns
// the paths written.
Result<nlohmann::json> writeOutputs(const std::string& dir, const std::string& name, const Outputs& outputs);

class Runner {
public:
    Runner(DemoDesc desc, Options options, const CLI::App& cli);
    int run();

private:
    Result<void> runHeadless();
    Result<void> runWindowed();                // app_window.cpp
    // The back buffer (demo output plus overlay) as <dir>/<name>_window.png.
    Result<void> writeWindowImage(const std::string& dir, const std::string& name, int width, int height);
    Result<void> resize(int width, int height);
    // Applies the camera path, runs the demo's frame between two glFinish calls, records its time.
    double timedFrame(const FrameInfo& info);  // milliseconds
    nlohmann::json report() const;

    DemoDesc desc_;
    const CLI::App& cli_;
    App app_;
    std::vector<double> frameMs_;              // measured (non-warm-up) frames
    int framesRendered_ = 0;
    int guiFrames_ = 0;                        // frames with the ImGui overlay drawn
    Stats stats_;
    nlohmann::json written_ = nlohmann::json::object();
    long glErrors_ = 0;
};

} // namespace rrc::demo
