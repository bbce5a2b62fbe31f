// Frames as OpenImageIO images: read back GL textures and framebuffers, write PNG/EXR, compare
// with explicit thresholds. Part of the rrc::image target.
#pragma once
#include <rrc/gl_object.hpp>

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace rrc {

// Reads a colour texture (any colour-renderable format) as float RGBA, or a depth texture as one
// float channel; rows top-down (flipped from GL's bottom-up order) so files look right.
OIIO::ImageBuf readTexture(GLuint texture, int level = 0);
// Reads a rectangle of `attachment` (GL_COLOR_ATTACHMENTi or GL_DEPTH_ATTACHMENT) of `framebuffer`.
OIIO::ImageBuf readFramebuffer(GLuint framebuffer, GLenum attachment, int width, int height);

// PNG (8-bit sRGB-encoded values as stored, clamped) or EXR (half float), chosen by extension.
Result<void> writeImage(const std::string& path, const OIIO::ImageBuf& image);
Result<OIIO::ImageBuf> readImage(const std::string& path);

struct CompareThresholds {
    float fail = 2.0f / 255.0f;     // a channel differing by more than this counts as failing
    double maxFailFraction = 0.001; // passes while at most this fraction of pixels fail
    float hardFail = 0.1f;          // any channel differing by more than this fails outright
};

struct CompareResult {
    double rmse = 0, psnr = 0, meanError = 0, maxError = 0;
    int maxX = 0, maxY = 0, maxChannel = 0;
    long failingPixels = 0;
    double failFraction = 0;
    bool passed = false;
};

// Compares same-sized images (ImageBufAlgo::compare); a size mismatch never passes.
CompareResult compareImages(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b,
                            const CompareThresholds& thresholds = {});

// |a - b| * gain, for looking at differences.
OIIO::ImageBuf differenceImage(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, float gain);

} // namespace rrc
