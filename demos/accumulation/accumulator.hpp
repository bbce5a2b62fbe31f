// The accumulation buffer (Haeberli and Akeley 1990) as a float target: every sample, brute force
// or cached, is added with weight 1/N by the same full-screen pass, so the variants integrate
// their samples identically and differ only in how each sample was made.
#pragma once
#include "common/fullscreen.hpp"

namespace rrc::accumulation {

class Accumulator {
public:
    // `library` gets common/shaders/* when it lacks them (rrc-bench's library does).
    Result<void> init(int width, int height, ShaderLibrary& library);
    void clear();
    // Adds texelFetch(texture) * weight to the target; the caller's weights should sum to one.
    void add(GLuint texture, float weight);
    GLuint result() const { return target_.id(); }   // GL_RGBA32F

private:
    int width_ = 0, height_ = 0;
    Texture target_;
    Framebuffer framebuffer_;
    demo::FullscreenPass pass_;
};

} // namespace rrc::accumulation
