// The bump-env demo's assets: the bump map turned into height slopes, the sky cube map, and the
// sphere they go on.
#include "bump_env_renderer.hpp"

#include <rrc/image.hpp>

#include <glm/vec3.hpp>

#include <cmath>

namespace rrc::bump_env {

Result<Texture> loadBumpSlopes(const std::string& path) {
    auto image = readImage(path);
    if (!image) return image.error();
    const OIIO::ImageSpec& spec = image.value().spec();
    const int w = spec.width, h = spec.height;
    if (w < 2 || h < 2) return fail(LogId::ImageReadFailed, "bump map " + path + " is too small");
    std::vector<float> height(static_cast<size_t>(w) * h), slopes(static_cast<size_t>(w) * h * 2);
    std::vector<float> px(spec.nchannels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            image.value().getpixel(x, y, px.data(), spec.nchannels);
            height[static_cast<size_t>(y) * w + x] = px[0];
        }
    auto at = [&](int x, int y) { return height[static_cast<size_t>((y + h) % h) * w + (x + w) % w]; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Rows are stored top-down: texture v grows downwards in the file, upwards in GL.
            const size_t i = (static_cast<size_t>(h - 1 - y) * w + x) * 2;
            slopes[i] = 0.5f * (at(x + 1, y) - at(x - 1, y));
            slopes[i + 1] = 0.5f * (at(x, y - 1) - at(x, y + 1));
        }
    Texture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, GL_RG32F, w, h);
    glTextureSubImage2D(t.id(), 0, 0, 0, w, h, GL_RG, GL_FLOAT, slopes.data());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    return t;
}

Result<Texture> loadCubeMap(const std::string& dir) {
    Texture t = createTexture(GL_TEXTURE_CUBE_MAP);
    const char* faces[] = {"px", "nx", "py", "ny", "pz", "nz"};   // GL's face order
    int size = 0;
    for (int face = 0; face < 6; ++face) {
        const std::string path = dir + "/" + faces[face] + ".png";
        auto image = readImage(path);
        if (!image) return image.error();
        const OIIO::ImageSpec& spec = image.value().spec();
        if (spec.width != spec.height || spec.nchannels < 3 || (size && spec.width != size))
            return fail(LogId::ImageReadFailed, "cube face " + path + " is not square RGB of the other faces' size");
        if (!size) {
            size = spec.width;
            glTextureStorage2D(t.id(), 1, GL_RGBA8, size, size);
        }
        std::vector<float> rgba(static_cast<size_t>(size) * size * 4, 1.0f), px(spec.nchannels);
        for (int y = 0; y < size; ++y)   // row 0 = the PNG's top row: no flip for cube faces
            for (int x = 0; x < size; ++x) {
                image.value().getpixel(x, y, px.data(), spec.nchannels);
                for (int c = 0; c < 3; ++c) rgba[(static_cast<size_t>(y) * size + x) * 4 + c] = px[c];
            }
        glTextureSubImage3D(t.id(), 0, 0, 0, face, size, size, 1, GL_RGBA, GL_FLOAT, rgba.data());
    }
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return t;
}

demo::MeshBuffers makeSphere(int slices, int stacks) {
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    for (int j = 0; j <= stacks; ++j)
        for (int i = 0; i <= slices; ++i) {
            const double theta = M_PI * j / stacks, phi = 2.0 * M_PI * i / slices;
            const glm::vec3 p(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
            vertices.insert(vertices.end(), {p.x, p.y, p.z, p.x, p.y, p.z});
        }
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const uint32_t a = uint32_t(j * (slices + 1) + i), b = a + uint32_t(slices + 1);
            indices.insert(indices.end(), {a, a + 1, b, a + 1, b + 1, b});   // counter-clockwise from outside
        }
    return demo::uploadMesh(vertices, indices);
}

} // namespace rrc::bump_env
