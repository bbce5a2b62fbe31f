// The trivial demo in a GLFW window (ctest runs it under xvfb-run): three frames with the ImGui
// overlay and the demo's gui callback, a window resize that reaches onResize, exit code 0.
// Skipped, with the reason, where no X server answers.
#include "run_helper.hpp"

#include <rrc/context.hpp>
#include <rrc/image.hpp>

#include <OpenImageIO/imagebufalgo.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

namespace rrc::demo::test {
namespace {

TEST(DemoWindow, GlfwRunsThreeFramesWithTheOverlay) {
    if (!displayAvailable()) GTEST_SKIP() << "no X server (DISPLAY unset or unreachable): run under xvfb-run";
    TempDir dir("window");
    Probe probe;
    probe.onFrame = [](App& app, const FrameInfo& info) {
        if (info.frame == 0) glfwSetWindowSize(app.window(), 120, 90);
    };
    const RunResult r = runTrivial({"--backend", "glfw", "--size", "96x64", "--frames", "3", "--warmup", "0", "--json",
                                    "--out", dir.str()}, trivialDemo(&probe));
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["backend"], "glfw");
    EXPECT_EQ(j["windowed"], true);
    EXPECT_EQ(j["gui_frames"], 3);
    EXPECT_EQ(j["frames"], 3);
    EXPECT_EQ(j["gl_errors"], 0);
    EXPECT_EQ(probe.guiCalls, 3);
    EXPECT_EQ(probe.frames, 3);
    ASSERT_FALSE(probe.resizes.empty()) << "the window resize never reached onResize";
    EXPECT_EQ(probe.resizes.back(), (std::pair{120, 90}));
    EXPECT_EQ(j["width"], 120);
    EXPECT_EQ(j["height"], 90);
    // The window as shown: the demo's image under a darker ImGui panel at the top left.
    auto demoImage = readImage((dir / "marble.png").string());
    auto window = readImage((dir / "marble_window.png").string());
    ASSERT_TRUE(demoImage.ok() && window.ok());
    EXPECT_EQ(window.value().spec().width, 120);
    EXPECT_EQ(window.value().spec().height, 90);
    const OIIO::ROI panel(12, 40, 12, 30, 0, 1, 0, 3);
    const auto diff = OIIO::ImageBufAlgo::compare(OIIO::ImageBufAlgo::cut(demoImage.value(), panel),
                                                  OIIO::ImageBufAlgo::cut(window.value(), panel), 1.0f, 1.0f);
    std::printf("window vs demo image under the overlay panel: mean difference %.3f\n", diff.meanerror);
    EXPECT_GT(diff.meanerror, 0.1) << "no ImGui panel drawn over the demo image";
}

} // namespace
} // namespace rrc::demo::test
