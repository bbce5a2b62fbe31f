// Full-screen passes: one triangle covering the viewport (no vertex buffer; the vertex shader
// derives it from gl_VertexID), for blits, composites and visualisations.
#pragma once
#include <rrc/shader.hpp>

#include <string>
#include <vector>

namespace rrc::demo {

// The library's common shaders ("common/shaders/*.glsl", ".vert", ".frag").
std::span<const EmbeddedFile> commonShaders();

// A program made of common/shaders/fullscreen.vert (it writes `demo_uv`, (0,0) at the lower-left
// corner of the viewport) and `fragment`, plus the empty vertex array core GL needs to draw.
class FullscreenPass {
public:
    static Result<FullscreenPass> create(const ShaderLibrary& library, const std::string& fragment,
                                         std::vector<Define> defines = {});
    GLuint program() const { return program_.id(); }
    // Uses the program and draws the triangle (depth test and blending are the caller's state).
    void draw() const;

private:
    Program program_;
    VertexArray vao_;
};

// Copies a texture to the bound framebuffer's viewport (bilinear if sizes differ).
// Options: `channel` >= 0 shows one channel as grey; `scale` multiplies the colour.
class Blitter {
public:
    static Result<Blitter> create(const ShaderLibrary& library);
    void draw(GLuint texture, float scale = 1.0f, int channel = -1) const;

private:
    FullscreenPass pass_;
};

} // namespace rrc::demo
