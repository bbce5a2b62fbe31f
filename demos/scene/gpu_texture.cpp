// Texture upload: full mip chain generated on the GPU; glTF's unset filters default to trilinear.
#include "gpu_texture.hpp"

#include <algorithm>
#include <bit>

namespace rrc::scene::detail {

Texture uploadTexture(const Image& image, const Sampler* sampler, bool srgb) {
    const GLsizei levels = GLsizei(std::bit_width(unsigned(std::max(image.width, image.height))));
    Texture texture = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), levels, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width, image.height);
    // Rows are tightly packed RGBA8; do not inherit a caller's unpack state.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glGenerateTextureMipmap(texture.id());
    const Sampler defaults;
    const Sampler& s = sampler ? *sampler : defaults;
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, s.minFilter ? s.minFilter : GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, s.magFilter ? s.magFilter : GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, s.wrapS);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, s.wrapT);
    return texture;
}

} // namespace rrc::scene::detail
