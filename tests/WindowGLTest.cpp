// The GLFW backend: a real window (under xvfb-run in ctest) renders and reads back. Skipped,
// with the reason, where no X server is available.
#include <rrc/context.hpp>
#include <rrc/debug.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>

namespace rrc::test {
namespace {

TEST(Window, GlfwWindowClearsAndReadsBack) {
    ::unsetenv("MESA_NO_ERROR");
    if (!displayAvailable()) GTEST_SKIP() << "no X server (DISPLAY unset or unreachable): GLFW needs one; run under xvfb-run";
    auto context = Context::create({.backend = Backend::Glfw, .width = 96, .height = 64, .title = "rrc window test"});
    ASSERT_TRUE(context.ok()) << context.error().message;
    EXPECT_EQ(context.value().backend(), Backend::Glfw);
    ASSERT_NE(context.value().window(), nullptr);
    resetDebugCounters();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, 96, 64);
    glClearColor(1.0f, 0.5f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 48, 64);
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    std::array<unsigned char, 4> left{}, right{};
    glReadBuffer(GL_BACK);
    glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, left.data());
    glReadPixels(80, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, right.data());
    context.value().swapBuffers();
    context.value().pollEvents();
    EXPECT_EQ(left, (std::array<unsigned char, 4>{0, 0, 255, 255}));
    EXPECT_EQ(right[0], 255);
    EXPECT_NEAR(right[1], 128, 1);
    EXPECT_EQ(right[2], 0);
    EXPECT_EQ(checkGLErrors("window test"), 0);
    EXPECT_EQ(debugCounters().debugErrors, 0);
}

} // namespace
} // namespace rrc::test
