// rrc-golden-compare: compares a rendered frame with its committed reference through
// rrc::compareImages (OpenImageIO's ImageBufAlgo::compare) with explicit thresholds; on failure
// writes the amplified difference beside the frame. Exit 0 pass, 1 fail, 2 unreadable input.
#include <rrc/image.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    CLI::App app{"rrc-golden-compare: a frame against its golden reference"};
    std::string reference, image, diff;
    rrc::CompareThresholds t;
    float gain = 8.0f;
    app.add_option("reference", reference, "committed reference PNG")->required();
    app.add_option("image", image, "frame to check")->required();
    app.add_option("--diff", diff, "where to write |image - reference| x gain when the check fails");
    app.add_option("--gain", gain, "difference amplification")->default_val(8.0f);
    app.add_option("--fail", t.fail, "a channel differing by more than this fails")->default_val(2.0f / 255.0f);
    app.add_option("--max-fail-fraction", t.maxFailFraction, "fraction of failing pixels allowed")->default_val(0.001);
    app.add_option("--hard-fail", t.hardFail, "any channel differing by more than this fails outright")->default_val(0.1f);
    CLI11_PARSE(app, argc, argv);

    auto ref = rrc::readImage(reference);
    if (!ref) { std::fprintf(stderr, "rrc-golden-compare: cannot read reference %s\n", reference.c_str()); return 2; }
    auto img = rrc::readImage(image);
    if (!img) { std::fprintf(stderr, "rrc-golden-compare: cannot read image %s\n", image.c_str()); return 2; }
    const rrc::CompareResult r = rrc::compareImages(img.value(), ref.value(), t);
    std::printf("%s: %s against %s: RMSE %.6f, PSNR %.1f dB, max %.4f at (%d, %d) channel %d, %ld pixels over %.4f "
                "(%.4f %%, allowed %.4f %%), hard fail above %.3f\n",
                r.passed ? "PASS" : "FAIL", image.c_str(), reference.c_str(), r.rmse, r.psnr, r.maxError, r.maxX, r.maxY,
                r.maxChannel, r.failingPixels, double(t.fail), 100.0 * r.failFraction, 100.0 * t.maxFailFraction,
                double(t.hardFail));
    if (r.passed) return 0;
    if (!diff.empty()) {
        if (auto w = rrc::writeImage(diff, rrc::differenceImage(img.value(), ref.value(), gain)); w)
            std::printf("difference x%g written to %s\n", double(gain), diff.c_str());
        else
            std::fprintf(stderr, "rrc-golden-compare: cannot write %s\n", diff.c_str());
    }
    return 1;
}
