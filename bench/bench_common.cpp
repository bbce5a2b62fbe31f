#include "bench_common.hpp"

#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace rrc::bench {

ErrorStats errorAgainst(const OIIO::ImageBuf& image, const OIIO::ImageBuf& reference, const OIIO::ImageBuf* mask,
                        float maskThreshold) {
    const int w = image.spec().width, h = image.spec().height;
    double sum = 0, maxError = 0;
    long n = 0;
    std::vector<float> a(4), b(4), m(1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (mask) {
                mask->getpixel(x, y, m.data(), 1);
                if (m[0] <= maskThreshold) continue;
            }
            image.getpixel(x, y, a.data(), 4);
            reference.getpixel(x, y, b.data(), 4);
            for (int c = 0; c < 3; ++c) {
                const double d = double(a[c]) - b[c];
                sum += d * d;
                maxError = std::max(maxError, std::abs(d));
            }
            ++n;
        }
    ErrorStats e;
    e.pixels = n;
    e.maxError = maxError;
    e.rmse = n ? std::sqrt(sum / (3.0 * n)) : 0.0;
    e.psnr = e.rmse > 0 ? 20.0 * std::log10(1.0 / e.rmse) : INFINITY;
    return e;
}

std::string savePng(const Options& options, GLuint texture, const std::string& name) {
    (void)writeImage(options.outDir + "/" + name, readTexture(texture));
    return name;
}

std::string saveDifference(const Options& options, const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, float gain,
                           const std::string& name) {
    OIIO::ImageBuf diff = differenceImage(a, b, gain);
    const float alpha = 1.0f;
    OIIO::ImageBufAlgo::fill(diff, &alpha, OIIO::ROI(0, diff.spec().width, 0, diff.spec().height, 0, 1, 3, 4));
    (void)writeImage(options.outDir + "/" + name, diff);
    return name;
}

namespace {

std::string number(std::optional<double> v) {
    if (!v || !std::isfinite(*v)) return v && std::isinf(*v) ? "1e999" : "null";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", *v);
    return buf;
}

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

} // namespace

void writeResults(const Options& options, const std::vector<Record>& records) {
    std::ofstream out(options.outDir + "/results.json");
    out << "[\n";
    for (size_t i = 0; i < records.size(); ++i) {
        const Record& r = records[i];
        std::optional<double> fraction;
        if (r.speedup && r.bestSpeedup && *r.bestSpeedup > 0) fraction = *r.speedup / *r.bestSpeedup;
        out << "  {\"demo\": " << quoted(r.demo) << ", \"variant\": " << quoted(r.variant) << ", \"samples\": " << r.samples
            << ", \"lambda\": " << number(r.lambda) << ", \"width\": " << r.width << ", \"height\": " << r.height
            << ", \"frames\": " << r.frames << ", \"ms_median\": " << number(r.timing.median)
            << ", \"ms_min\": " << number(r.timing.min) << ", \"rmse\": " << number(r.rmse) << ", \"psnr\": " << number(r.psnr)
            << ", \"hit_rate\": " << number(r.hitRate) << ", \"speedup\": " << number(r.speedup)
            << ", \"best_speedup\": " << number(r.bestSpeedup) << ", \"fraction_of_best\": " << number(fraction);
        for (const auto& [k, v] : r.extra) out << ", " << quoted(k) << ": " << number(v);
        out << ", \"note\": " << quoted(r.note) << ", \"images\": {";
        bool first = true;
        for (const auto& [k, v] : r.images) {
            out << (first ? "" : ", ") << quoted(k) << ": " << quoted(v);
            first = false;
        }
        out << "}}" << (i + 1 < records.size() ? "," : "") << "\n";
    }
    out << "]\n";
}

} // namespace rrc::bench
