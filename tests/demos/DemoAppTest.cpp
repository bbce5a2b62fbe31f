// runDemo() headless on EGL and OSMesa: exit codes, the JSON report, image output, determinism,
// and the rejection of bad options (exit code 1 with a message on stderr).
#include "run_helper.hpp"

#include <common/app_internal.hpp>

#include <rrc/image.hpp>

#include <OpenImageIO/imagebufalgo.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>

namespace rrc::demo::test {
namespace {

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class DemoHeadless : public ::testing::TestWithParam<std::string> {};

TEST_P(DemoHeadless, RunsWritesJsonAndImages) {
    TempDir dir("out");
    Probe probe;
    const RunResult r = runTrivial({"--backend", GetParam(), "--size", "64x48", "--frames", "3", "--json", "--out", dir.str()},
                                   trivialDemo(&probe));
    ASSERT_EQ(r.code, 0) << r.err;
    nlohmann::json j;
    ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << "stdout is not one JSON object:\n" << r.out;
    ASSERT_TRUE(j.is_object());
    for (const char* key : {"options", "stats", "timings", "ms_median", "ms_min", "frames", "backend", "renderer", "width", "height"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["backend"], GetParam());
    EXPECT_EQ(j["width"], 64);
    EXPECT_EQ(j["height"], 48);
    EXPECT_EQ(j["frames"], 3);
    EXPECT_EQ(j["timings"]["frame_ms"].size(), 3u);
    EXPECT_GT(j["ms_median"].get<double>(), 0.0);
    EXPECT_LE(j["ms_min"].get<double>(), j["ms_median"].get<double>());
    EXPECT_FALSE(j["renderer"].get<std::string>().empty());
    EXPECT_EQ(j["gl_errors"], 0);
    EXPECT_EQ(j["options"]["size"], "64x48");
    EXPECT_EQ(j["options"]["octaves"], 5);   // the demo's own option, with its default
    EXPECT_EQ(j["options"]["json"], true);
    EXPECT_EQ(j["stats"]["octaves"], 5);
    EXPECT_EQ(j["stats"]["cached"], 1);
    EXPECT_EQ(probe.inits, 1);
    EXPECT_EQ(probe.frames, 3 + 5);            // + the default warm-up
    EXPECT_EQ(probe.cleanups, 1);
    for (const char* file : {"marble.png", "marble.exr", "marble_hitmiss.png"}) {
        ASSERT_TRUE(std::filesystem::exists(dir / file)) << file;
        auto image = readImage((dir / file).string());
        ASSERT_TRUE(image.ok());
        EXPECT_EQ(image.value().spec().width, 64);
        EXPECT_EQ(image.value().spec().height, 48);
    }
    // The EXR keeps the unclamped float colour; marble is not a constant image.
    auto exr = readImage((dir / "marble.exr").string()).value();
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(exr);
    EXPECT_LT(stats.min[0], stats.max[0]);
    std::printf("[ %-8s ] 64x48 marble: median %.3f ms, min %.3f ms on %s\n", GetParam().c_str(),
                j["ms_median"].get<double>(), j["ms_min"].get<double>(), j["renderer"].get<std::string>().c_str());
}

TEST_P(DemoHeadless, TwoRunsGiveBitIdenticalImages) {
    TempDir a("det_a"), b("det_b");
    const std::vector<std::string> args{"--backend", GetParam(), "--size", "64x48", "--frames", "4", "--warmup", "2", "--seed", "7"};
    auto withOut = [&](const TempDir& d) { auto v = args; v.insert(v.end(), {"--out", d.str()}); return v; };
    ASSERT_EQ(runTrivial(withOut(a)).code, 0);
    ASSERT_EQ(runTrivial(withOut(b)).code, 0);
    const std::string pa = fileBytes(a / "marble.png"), pb = fileBytes(b / "marble.png");
    ASSERT_FALSE(pa.empty());
    EXPECT_TRUE(pa == pb) << "two identical runs wrote different PNGs";
    EXPECT_TRUE(fileBytes(a / "marble_hitmiss.png") == fileBytes(b / "marble_hitmiss.png"));
    // Another seed is another noise field (so the seed really reaches the shader).
    TempDir c("det_c");
    auto other = withOut(c);
    other[9] = "8";
    ASSERT_EQ(runTrivial(other).code, 0);
    EXPECT_FALSE(fileBytes(c / "marble.png") == pa);
}

TEST_P(DemoHeadless, ModeSeedAndDemoOptionsReachTheDemo) {
    const RunResult r = runTrivial({"--backend", GetParam(), "--size", "32x32", "--frames", "1", "--warmup", "0", "--json",
                                    "--mode", "brute", "--octaves", "2", "--material", "wood", "--seed", "3"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["mode"], "brute");
    EXPECT_EQ(j["stats"]["cached"], 0);
    EXPECT_EQ(j["stats"]["octaves"], 2);
    EXPECT_EQ(j["options"]["material"], "wood");
    EXPECT_EQ(j["options"]["seed"], 3);
    EXPECT_EQ(j["frames"], 1);
    EXPECT_EQ(j["gl_errors"], 0);
}

INSTANTIATE_TEST_SUITE_P(Backends, DemoHeadless, ::testing::Values("egl", "osmesa"),
                         [](const auto& info) { return info.param; });

TEST(DemoOptions, BadSizeFailsWithExitCode1AndAMessage) {
    for (const char* size : {"abc", "0x10", "10x", "x10", "64x48x2", "-5x5", "99999x10", "64 x 48"}) {
        const RunResult r = runTrivial({"--backend", "egl", "--size", size});
        EXPECT_EQ(r.code, 1) << size;
        EXPECT_NE(r.err.find("--size"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("WIDTHxHEIGHT"), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

TEST(DemoOptions, OtherBadOptionsFailWithExitCode1) {
    const std::vector<std::vector<std::string>> cases{
        {"--backend", "vulkan"}, {"--mode", "fast"}, {"--frames", "0"}, {"--frames", "many"}, {"--warmup", "-1"},
        {"--scene", "/nonexistent/scene.gltf"}, {"--seed", "-3"}, {"--octaves", "0"}, {"--no-such-option"}};
    for (const auto& args : cases) {
        const RunResult r = runTrivial(args);
        EXPECT_EQ(r.code, 1) << args[0];
        EXPECT_FALSE(r.err.empty()) << args[0];
    }
}

TEST(DemoOptions, HelpExitsWith0AndListsTheOptions) {
    const RunResult r = runTrivial({"--help"});
    EXPECT_EQ(r.code, 0);
    for (const char* opt : {"--backend", "--size", "--frames", "--mode", "--scene", "--out", "--json", "--seed", "--warmup", "--octaves"})
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST(DemoOptions, InitFailureExitsWith2AndStillCleansUp) {
    Probe probe;
    probe.failInit = true;
    const RunResult r = runTrivial({"--backend", "egl", "--size", "16x16", "--frames", "1"}, trivialDemo(&probe));
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("init failure requested"), std::string::npos) << r.err;
    EXPECT_EQ(probe.frames, 0);
    EXPECT_EQ(probe.cleanups, 1);
}

TEST(DemoOptions, ParseSize) {
    EXPECT_EQ(parseSize("1024x768"), (std::pair{1024, 768}));
    EXPECT_EQ(parseSize("1X1"), (std::pair{1, 1}));
    EXPECT_FALSE(parseSize("abc"));
    EXPECT_FALSE(parseSize("16385x10"));
    EXPECT_FALSE(parseSize("+5x5"));
}

} // namespace
} // namespace rrc::demo::test
