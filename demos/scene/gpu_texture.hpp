// Internal to GpuScene: one glTF image as an immutable, mipmapped GL texture with the glTF
// sampler's filtering and wrapping (rrc has no sampler-object wrapper, so they live on the texture).
#pragma once
#include "scene.hpp"

#include <rrc/gl_object.hpp>

namespace rrc::scene::detail {

// GL_SRGB8_ALPHA8 when `srgb` (base colour), GL_RGBA8 otherwise (normal maps). `sampler` may be null.
Texture uploadTexture(const Image& image, const Sampler* sampler, bool srgb);

} // namespace rrc::scene::detail
