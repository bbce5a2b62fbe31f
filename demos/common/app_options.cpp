// The common command line (CLI11), the options echoed into the JSON report, and image output.
// CLI11 exits with codes 100+; runDemo maps every parse failure to 1 (help to 0).
#include "app_internal.hpp"

#include <rrc/image.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <filesystem>

namespace rrc::demo {
namespace {

constexpr int kMaxSize = 16384;

int parseDimension(std::string_view text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const bool ok = error == std::errc() && end == text.data() + text.size() && value >= 1 && value <= kMaxSize;
    return ok ? value : 0;
}

// A JSON integer or number when the whole text is one, else the text.
nlohmann::json scalar(const std::string& text) {
    if (text.empty()) return text;
    long long integer = 0;
    const auto [last, error] = std::from_chars(text.data(), text.data() + text.size(), integer);
    if (error == std::errc() && last == text.data() + text.size()) return integer;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() ? nlohmann::json(value) : nlohmann::json(text);
}

} // namespace

std::optional<std::pair<int, int>> parseSize(std::string_view text) {
    const size_t x = text.find_first_of("xX");
    if (x == std::string_view::npos) return std::nullopt;
    const int w = parseDimension(text.substr(0, x)), h = parseDimension(text.substr(x + 1));
    if (w == 0 || h == 0) return std::nullopt;
    return std::pair{w, h};
}

std::optional<int> parseCommandLine(int argc, char** argv, CLI::App& cli, Options& o, const DemoDesc& desc) {
    cli.option_defaults()->always_capture_default();
    std::string backend = "auto", size = "1024x768", mode = "cached";
    const CLI::Validator sizeCheck(
        [](std::string& text) {
            return parseSize(text) ? std::string()
                                   : "expected WIDTHxHEIGHT with each in 1.." + std::to_string(kMaxSize) + " (e.g. 1024x768), got '" + text + "'";
        },
        "WxH");
    cli.add_option("--backend", backend, "GL backend: auto (RRC_GL_BACKEND, else GLFW if a display works, else EGL, else OSMesa), egl, osmesa, glfw")
        ->check(CLI::IsMember({"auto", "egl", "osmesa", "glfw"}, CLI::ignore_case));
    cli.add_option("--size", size, "render size (and initial window size)")->check(sizeCheck);
    CLI::Option* frames = cli.add_option("--frames", o.frames, "measured frames (headless run length; a window runs until closed unless given)")
                              ->check(CLI::Range(1, 10000000));
    cli.add_option("--warmup", o.warmup, "frames rendered before the measured ones")->check(CLI::Range(0, 10000000));
    cli.add_option("--mode", mode, "brute force or with the reprojection cache")->check(CLI::IsMember({"brute", "cached"}, CLI::ignore_case));
    cli.add_option("--scene", o.scene, "glTF scene file (default: the demo's own)")->check(CLI::ExistingFile);
    cli.add_option("--out", o.out, "write the last frame to DIR/<demo>.png, .exr (and <demo>_hitmiss.png)");
    cli.add_flag("--json", o.json, "print one JSON object (options, stats, timings) on stdout");
    cli.add_option("--seed", o.seed, "random seed");
    if (desc.addOptions) desc.addOptions(cli);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return cli.exit(e) == 0 ? 0 : 1;   // CLI11 prints help or the reason; its codes are 100+
    }
    o.backend = parseBackend(backend).value();   // the check above admits only valid names
    const auto wh = parseSize(size).value();
    o.width = wh.first;
    o.height = wh.second;
    o.framesGiven = frames->count() > 0;
    std::transform(mode.begin(), mode.end(), mode.begin(), [](unsigned char c) { return std::tolower(c); });
    o.mode = mode == "brute" ? Mode::Brute : Mode::Cached;
    return std::nullopt;
}

nlohmann::json optionsJson(const CLI::App& cli) {
    nlohmann::json out = nlohmann::json::object();
    for (const CLI::Option* opt : cli.get_options()) {
        const std::string name = opt->get_single_name();
        if (opt->get_lnames().empty() || name == "help") continue;
        if (opt->get_expected_min() == 0) {   // a flag
            out[name] = opt->count() > 0;
            continue;
        }
        const std::vector<std::string> results = opt->reduced_results();
        if (results.empty()) out[name] = scalar(opt->get_default_str());
        else if (results.size() == 1) out[name] = scalar(results.front());
        else {
            nlohmann::json values = nlohmann::json::array();
            for (const std::string& r : results) values.push_back(scalar(r));
            out[name] = values;
        }
    }
    return out;
}

Result<nlohmann::json> writeOutputs(const std::string& dir, const std::string& name, const Outputs& outputs) {
    if (outputs.color == 0) return fail(LogId::ImageWriteFailed, "--out: the demo exposes no colour texture");
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) return fail(LogId::ImageWriteFailed, "--out: cannot create " + dir + ": " + error.message());
    nlohmann::json written = nlohmann::json::object();
    const OIIO::ImageBuf color = readTexture(outputs.color);
    for (const char* ext : {"png", "exr"}) {
        const std::string path = (std::filesystem::path(dir) / (name + "." + ext)).string();
        if (auto r = writeImage(path, color); !r) return r.error();
        written[ext] = path;
    }
    if (outputs.visualization != 0) {
        const std::string path = (std::filesystem::path(dir) / (name + "_hitmiss.png")).string();
        if (auto r = writeImage(path, readTexture(outputs.visualization)); !r) return r.error();
        written["hitmiss_png"] = path;
    }
    return written;
}

} // namespace rrc::demo
