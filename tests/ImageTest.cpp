// Image comparison and file round trips on OpenImageIO (no GL).
#include <rrc/image.hpp>

#include "support/log_capture.hpp"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace rrc::test {
namespace {

OIIO::ImageBuf flat(int w, int h, float v) {
    OIIO::ImageBuf image(OIIO::ImageSpec(w, h, 4, OIIO::TypeDesc::FLOAT));
    const float c[4] = {v, v, v, 1.0f};
    OIIO::ImageBufAlgo::fill(image, c);
    return image;
}

TEST(ImageCompare, IdenticalImagesPass) {
    auto r = compareImages(flat(16, 16, 0.5f), flat(16, 16, 0.5f));
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(r.rmse, 0.0);
    EXPECT_EQ(r.failingPixels, 0);
}

TEST(ImageCompare, ReportsMaxErrorLocationAndFailFraction) {
    auto a = flat(20, 10, 0.5f);
    auto b = flat(20, 10, 0.5f);
    const float px[4] = {0.5f, 0.9f, 0.5f, 1.0f};
    b.setpixel(7, 3, px);
    auto r = compareImages(a, b, {.fail = 2.0f / 255, .maxFailFraction = 0.01, .hardFail = 0.5f});
    EXPECT_NEAR(r.maxError, 0.4, 1e-6);
    EXPECT_EQ(r.maxX, 7);
    EXPECT_EQ(r.maxY, 3);
    EXPECT_EQ(r.maxChannel, 1);
    EXPECT_EQ(r.failingPixels, 1);
    EXPECT_NEAR(r.failFraction, 1.0 / 200, 1e-12);
    EXPECT_TRUE(r.passed);   // 0.5% of pixels fail, 1% allowed, below the hard limit
    EXPECT_FALSE(compareImages(a, b, {.fail = 2.0f / 255, .maxFailFraction = 0.001, .hardFail = 0.5f}).passed);
    EXPECT_FALSE(compareImages(a, b, {.fail = 2.0f / 255, .maxFailFraction = 0.5, .hardFail = 0.1f}).passed);
}

TEST(ImageCompare, SizeMismatchNeverPasses) {
    EXPECT_FALSE(compareImages(flat(8, 8, 0), flat(8, 9, 0)).passed);
}

TEST(ImageFiles, PngAndExrRoundTrip) {
    const auto dir = std::filesystem::temp_directory_path() / "rrc_image_test";
    std::filesystem::create_directories(dir);
    auto image = flat(8, 4, 0.25f);
    ASSERT_TRUE(writeImage((dir / "a.exr").string(), image).ok());
    ASSERT_TRUE(writeImage((dir / "a.png").string(), image).ok());
    auto exr = readImage((dir / "a.exr").string());
    auto png = readImage((dir / "a.png").string());
    ASSERT_TRUE(exr.ok() && png.ok());
    EXPECT_EQ(compareImages(exr.value(), image, {.fail = 0}).maxError, 0.0);  // 0.25 is exact in half
    EXPECT_LE(compareImages(png.value(), image).maxError, 0.5 / 255 + 1e-6);
    std::filesystem::remove_all(dir);
}

TEST(ImageFiles, UnreadableFileIsAnErrorNamingTheFile) {
    LogCapture log;
    auto r = readImage("/nonexistent/rrc/missing.png");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().id, LogId::ImageReadFailed);
    EXPECT_NE(r.error().message.find("missing.png"), std::string::npos);
}

} // namespace
} // namespace rrc::test
