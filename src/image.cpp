// GL readback into OpenImageIO buffers, file I/O and thresholded comparison.
#include <rrc/image.hpp>

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rrc {
namespace {

bool isDepthFormat(GLint internalFormat) {
    switch (internalFormat) {
    case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8: case GL_DEPTH32F_STENCIL8:
    case GL_DEPTH_COMPONENT: return true;
    default: return false;
    }
}

// GL rows go bottom-up; files go top-down.
OIIO::ImageBuf fromBottomUp(const std::vector<float>& pixels, int width, int height, int channels) {
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf image(spec);
    const auto rowFloats = static_cast<size_t>(width) * channels;
    for (int y = 0; y < height; ++y) {
        const float* row = pixels.data() + static_cast<size_t>(height - 1 - y) * rowFloats;
        image.set_pixels(OIIO::ROI(0, width, y, y + 1, 0, 1, 0, channels), OIIO::TypeDesc::FLOAT, row);
    }
    return image;
}

bool hasExtension(const std::string& path, const char* ext) {
    const auto dot = path.rfind('.');
    if (dot == std::string::npos) return false;
    std::string e = path.substr(dot + 1);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e == ext;
}

} // namespace

OIIO::ImageBuf readTexture(GLuint texture, int level) {
    GLint width = 0, height = 0, format = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_INTERNAL_FORMAT, &format);
    const bool depth = isDepthFormat(format);
    const int channels = depth ? 1 : 4;
    std::vector<float> pixels(static_cast<size_t>(width) * height * channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture, level, depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(pixels.size() * sizeof(float)), pixels.data());
    return fromBottomUp(pixels, width, height, channels);
}

OIIO::ImageBuf readFramebuffer(GLuint framebuffer, GLenum attachment, int width, int height) {
    const bool depth = attachment == GL_DEPTH_ATTACHMENT;
    const int channels = depth ? 1 : 4;
    std::vector<float> pixels(static_cast<size_t>(width) * height * channels);
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (!depth) glNamedFramebufferReadBuffer(framebuffer, attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, pixels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
    return fromBottomUp(pixels, width, height, channels);
}

Result<void> writeImage(const std::string& path, const OIIO::ImageBuf& image) {
    OIIO::ImageBuf out = image;
    if (hasExtension(path, "png")) {
        out = OIIO::ImageBufAlgo::clamp(image, 0.0f, 1.0f);
        out.set_write_format(OIIO::TypeDesc::UINT8);
    } else if (hasExtension(path, "exr")) {
        out.set_write_format(OIIO::TypeDesc::HALF);
    }
    if (!out.write(path))
        return fail(LogId::ImageWriteFailed, "cannot write image " + path + ": " + out.geterror());
    return {};
}

Result<OIIO::ImageBuf> readImage(const std::string& path) {
    OIIO::ImageBuf image(path);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT))
        return fail(LogId::ImageReadFailed, "cannot read image " + path + ": " + image.geterror());
    return image;
}

CompareResult compareImages(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const CompareThresholds& t) {
    CompareResult result;
    const auto& sa = a.spec();
    const auto& sb = b.spec();
    if (sa.width != sb.width || sa.height != sb.height || sa.nchannels != sb.nchannels) {
        result.maxError = INFINITY;
        result.rmse = INFINITY;
        result.failFraction = 1.0;
        return result;
    }
    const auto stats = OIIO::ImageBufAlgo::compare(a, b, t.fail, t.fail);
    result.rmse = stats.rms_error;
    result.psnr = stats.PSNR;
    result.meanError = stats.meanerror;
    result.maxError = stats.maxerror;
    result.maxX = stats.maxx;
    result.maxY = stats.maxy;
    result.maxChannel = stats.maxc;
    result.failingPixels = static_cast<long>(stats.nfail);
    const double pixels = static_cast<double>(sa.width) * sa.height;
    result.failFraction = pixels > 0 ? static_cast<double>(stats.nfail) / pixels : 0.0;
    result.passed = std::isfinite(stats.maxerror) && stats.maxerror <= t.hardFail &&
                    result.failFraction <= t.maxFailFraction;
    return result;
}

OIIO::ImageBuf differenceImage(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, float gain) {
    OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(a, b);
    return OIIO::ImageBufAlgo::mul(diff, gain);
}

} // namespace rrc
