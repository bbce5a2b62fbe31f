// Shared by the amortized-supersampling runners (shadows_bench.cpp, bump_env_bench.cpp): fast
// RGBA8 read-back and RMSE (the per-pixel OIIO path is too slow for per-frame convergence
// curves), interleaved timing tallies, and the JSON side file of per-frame series.
#pragma once
#include "bench_common.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace rrc::bench::amortized {

using Pixels = std::vector<uint8_t>;

inline Pixels readRgba8(GLuint texture, int width, int height) {
    Pixels p(static_cast<size_t>(width) * height * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(p.size()), p.data());
    return p;
}

// RMSE over the RGB channels in [0, 1] units, as bench_common's errorAgainst.
inline double rmse(const Pixels& a, const Pixels& b) {
    double sum = 0;
    for (size_t i = 0; i < a.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
            const double d = (double(a[i + c]) - double(b[i + c])) / 255.0;
            sum += d * d;
        }
    return std::sqrt(sum / std::max<double>(1.0, 3.0 * double(a.size() / 4)));
}

// The first three fields of /proc/loadavg: the machine is shared, timings are read with it.
inline std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

inline double psnr(double e) { return e > 0 ? 20.0 * std::log10(1.0 / e) : INFINITY; }

// Wall-clock milliseconds of `work` between two glFinish calls.
template <class F> double timeOnce(F&& work) {
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// One variant's numbers over the interleaved frames.
struct Tally {
    std::vector<double> ms;
    double error2 = 0;   // sum of squared RMSEs over the checked frames
    int checked = 0;
    void addError(double e) { error2 += e * e; ++checked; }
    double rmse() const { return checked ? std::sqrt(error2 / checked) : 0.0; }
    demo::Timing timing() {
        std::sort(ms.begin(), ms.end());
        return ms.empty() ? demo::Timing{} : demo::Timing{ms[ms.size() / 2], ms.front(), int(ms.size())};
    }
};

// {"name": [v0, v1, ...], ...} for the report scripts (scripts/report/<demo>.py).
inline void writeSeries(const Options& options, const std::string& file, const std::map<std::string, std::vector<double>>& series) {
    std::ofstream out(options.outDir + "/" + file);
    out << "{";
    bool first = true;
    for (const auto& [name, values] : series) {
        out << (first ? "" : ",") << "\n  \"" << name << "\": [";
        for (size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << (std::isfinite(values[i]) ? values[i] : -1.0);
        out << "]";
        first = false;
    }
    out << "\n}\n";
}

inline void saveRgba8Difference(const Options& options, const Pixels& a, const Pixels& b, int width, int height, float gain,
                                const std::string& name, Record& record, const std::string& label) {
    OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = (static_cast<size_t>(height - 1 - y) * width + x) * 4;   // GL rows are bottom-up
            float px[3];
            for (int c = 0; c < 3; ++c) px[c] = std::min(1.0f, gain * std::abs(float(a[i + c]) - float(b[i + c])) / 255.0f);
            image.setpixel(x, y, px, 3);
        }
    if (writeImage(options.outDir + "/" + name, image)) record.images[label] = name;
}

} // namespace rrc::bench::amortized
