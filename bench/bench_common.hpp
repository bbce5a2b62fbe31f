// What every rrc-bench demo runner shares: options, result records, image output and error
// metrics against a reference.
#pragma once
#include <rrc/cache.hpp>
#include <rrc/image.hpp>

#include "support/flow_option.hpp"
#include "support/timing.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rrc::bench {

struct Options {
    std::string outDir = "out";
    int width = 1024, height = 768;
    int frames = 30, warmup = 5;
    std::string scene = "assets/temple.glb";
    bool smoke = false, full = false;
    double eyeSeparation = 0.065;   // stereo: metres (human interocular distance)
    std::string flow = "one-pass";  // cached variants: one-pass, two-pass, two-pass-no-probe

    ControlFlow cachedFlow() const { return demo::flowNamed(flow); }
    bool probe() const { return demo::probeNamed(flow); }   // FrameDesc::skipEmptyMissPass
};

struct Record {
    std::string demo, variant;
    int samples = 1;
    std::optional<double> lambda;
    int width = 0, height = 0, frames = 0;
    demo::Timing timing;
    std::optional<double> rmse, psnr, hitRate, speedup, bestSpeedup;
    std::map<std::string, double> extra;          // demo-specific numbers (e.g. psnr_specular)
    std::map<std::string, std::string> images;    // label -> file name inside outDir
    std::string note;
};

// Error of `image` against `reference` (RGB only); `mask` (one channel, same size) restricts it
// to pixels where mask > maskThreshold.
struct ErrorStats { double rmse = 0, psnr = 0, maxError = 0; long pixels = 0; };
ErrorStats errorAgainst(const OIIO::ImageBuf& image, const OIIO::ImageBuf& reference, const OIIO::ImageBuf* mask = nullptr,
                        float maskThreshold = 0.5f);

// Writes a texture as PNG into the output folder; returns the file name.
std::string savePng(const Options& options, GLuint texture, const std::string& name);
// |a - b| * gain as PNG.
std::string saveDifference(const Options& options, const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, float gain,
                           const std::string& name);

void writeResults(const Options& options, const std::vector<Record>& records);

} // namespace rrc::bench
