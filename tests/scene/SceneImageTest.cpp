// The image decoder tinygltf calls: it refuses a bufferView range outside its buffer before
// reading (tinygltf forms the pointer unchecked), formats other than PNG/JPEG, and images larger
// than LoadOptions allow.
#include "support/log_capture.hpp"

#include "gltf_image.hpp"
#include "load_context.hpp"

#include <gtest/gtest.h>

namespace rrc::test {
namespace {

using scene::detail::LoadContext;
using scene::detail::loadImageData;

const unsigned char kPngSignature[16] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

TEST(SceneImage, RefusesABufferViewOutsideItsBuffer) {
    LoadContext context;
    context.bufferLengths = {100};
    context.views = {{.buffer = 0, .offset = 90, .length = 16}};  // bytes 90..106 of a 100-byte buffer
    tinygltf::Image image;
    image.bufferView = 0;
    std::string err;
    EXPECT_FALSE(loadImageData(&image, 3, &err, nullptr, 0, 0, kPngSignature, 16, &context));
    EXPECT_NE(err.find("image 3: bufferView 0 lies outside its buffer"), std::string::npos) << err;
    image.bufferView = 7;
    err.clear();
    EXPECT_FALSE(loadImageData(&image, 3, &err, nullptr, 0, 0, kPngSignature, 16, &context));
    EXPECT_NE(err.find("does not exist"), std::string::npos) << err;
}

TEST(SceneImage, RefusesOtherFormats) {
    LoadContext context;
    tinygltf::Image image;
    const unsigned char gif[] = "GIF89a.........";
    std::string err;
    EXPECT_FALSE(loadImageData(&image, 0, &err, nullptr, 0, 0, gif, int(sizeof gif), &context));
    EXPECT_NE(err.find("not a PNG or JPEG"), std::string::npos) << err;
    err.clear();
    EXPECT_FALSE(loadImageData(&image, 0, &err, nullptr, 0, 0, kPngSignature, 16, &context));  // header only
    EXPECT_NE(err.find("cannot decode"), std::string::npos) << err;
}

TEST(SceneImage, SizeLimitFromTheHeader) {
    LogCapture log;
    // temple.glb holds two 256x256 PNGs.
    auto s = scene::loadScene(std::string(RRC_SCENE_ASSETS) + "/temple.glb", {.maxImageSize = 128});
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("image 0: size 256x256 is outside 1..128"), std::string::npos) << s.error().message;
}

} // namespace
} // namespace rrc::test
